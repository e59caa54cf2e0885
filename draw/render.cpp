// The rasteriser of render.h: camera, framing, z-buffered flat-shaded triangles with edge
// lines, supersampling. Single-threaded on purpose: identical pixels on every run.
#include "msmesh/render.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <utility>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/parameters.h"
#include "msmesh/topology.h"

namespace msmesh {

// ---------------------------------------------------------------------------------------
// Views and options
// ---------------------------------------------------------------------------------------

std::vector<std::string> view_names() { return {"iso", "front", "back", "left", "right", "top", "bottom"}; }

View view_from_name(const std::string& name) {
  static const View views[] = {View::Iso, View::Front, View::Back, View::Left, View::Right, View::Top, View::Bottom};
  const std::vector<std::string> names = view_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return views[i];
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InvalidInput("unknown view '" + name + "'; valid: " + list);
}

std::vector<std::string> up_axis_names() { return {"x", "-x", "y", "-y", "z", "-z"}; }

UpAxis up_axis_from_name(const std::string& name) {
  static const UpAxis axes[] = {UpAxis::PosX, UpAxis::NegX, UpAxis::PosY, UpAxis::NegY, UpAxis::PosZ, UpAxis::NegZ};
  const std::vector<std::string> names = up_axis_names();
  const std::string n = !name.empty() && name[0] == '+' ? name.substr(1) : name;
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == n) return axes[i];
  std::string list;
  for (const auto& a : names) list += (list.empty() ? "" : ", ") + a;
  throw InvalidInput("unknown up axis '" + name + "'; valid: " + list);
}

std::string up_axis_name(UpAxis axis) { return up_axis_names()[static_cast<size_t>(axis)]; }

const ParameterTable<RenderOptions>& render_parameters() {
  using O = RenderOptions;
  using T = ParameterType;
  const char* const g = "render";
  static const ParameterTable<O> t = {
      bind_parameter(ParameterInfo{"width", "", "pixels", T::Integer, {1, 16384}, "picture width", g}, &O::width),
      bind_parameter(ParameterInfo{"height", "", "pixels", T::Integer, {1, 16384}, "picture height", g}, &O::height),
      bind_parameter(ParameterInfo{"supersample", "", "", T::Integer, {1, 4}, "samples per pixel along each axis", g},
                     &O::supersample),
      bind_parameter(ParameterInfo{"fov", "", "degrees", T::Real, {0, 120, true, true}, "perspective field of view", g},
                     &O::fov_deg),
      bind_parameter(ParameterInfo{"margin", "", "", T::Real, {0, 0.45}, "empty fraction on each side", g}, &O::margin),
      bind_parameter(ParameterInfo{"ambient", "", "", T::Real, {0}, "ambient shade", g}, &O::ambient),
      bind_parameter(ParameterInfo{"diffuse", "", "", T::Real, {0}, "diffuse shade", g}, &O::diffuse),
      bind_parameter(ParameterInfo{"line-width", "", "pixels", T::Real, {0, 20, true, false}, "width of edge lines", g},
                     &O::line_width),
      bind_parameter(
          ParameterInfo{
              "azimuth", "", "degrees", T::Real, {-360, 360}, "camera turn about the up axis from the named view", g},
          &O::azimuth_deg),
      bind_parameter(ParameterInfo{"elevation",
                                   "",
                                   "degrees",
                                   T::Real,
                                   {-90, 90},
                                   "camera raised towards the up axis from the named view",
                                   g},
                     &O::elevation_deg),
  };
  return t;
}

void RenderOptions::validate() const {
  check_parameters(render_parameters(), *this);
  if (!light.allFinite() || light.norm() == 0)
    throw InvalidInput("render option light must be a non-zero finite vector");
  if (frame_points.size() != 0 && (frame_points.cols() != 3 || !frame_points.allFinite()))
    throw InvalidInput("render option frame_points must be #P by 3 and finite");
  if (!background.allFinite() || !base_color.allFinite())
    throw InvalidInput("render options background and base_color must be finite");
  if (static_cast<long long>(width) * height * supersample * supersample > 400'000'000LL)
    throw InvalidInput("render size " + std::to_string(width) + "x" + std::to_string(height) + " with supersample " +
                       std::to_string(supersample) + " is too large");
}

namespace {

/// Orthonormal camera frame: `right`, `up`, and `back` pointing from the scene to the viewer.
struct CameraFrame {
  Eigen::Vector3d right, up, back;
};

/// The camera frame of a named view in the +y-up frame of View.
CameraFrame view_frame(View view) {
  CameraFrame c;
  switch (view) {
    case View::Front:
      c.back = {0, 0, 1};
      c.up = {0, 1, 0};
      break;
    case View::Back:
      c.back = {0, 0, -1};
      c.up = {0, 1, 0};
      break;
    case View::Right:
      c.back = {1, 0, 0};
      c.up = {0, 1, 0};
      break;
    case View::Left:
      c.back = {-1, 0, 0};
      c.up = {0, 1, 0};
      break;
    case View::Top:
      c.back = {0, 1, 0};
      c.up = {0, 0, -1};
      break;
    case View::Bottom:
      c.back = {0, -1, 0};
      c.up = {0, 0, 1};
      break;
    case View::Iso:
      c.back = Eigen::Vector3d(1, 1, 1).normalized();
      c.up = (Eigen::Vector3d(0, 1, 0) - c.back * c.back.y()).normalized();
      break;
  }
  c.right = c.up.cross(c.back);
  return c;
}

/// The world directions of the x, y (up) and z axes of View's frame, as matrix columns: a
/// rotation (right-handed, determinant 1), see UpAxis.
Eigen::Matrix3d up_axis_frame(UpAxis up) {
  Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY();
  switch (up) {
    case UpAxis::PosY:
      x = {1, 0, 0}, y = {0, 1, 0};
      break;
    case UpAxis::NegY:
      x = {1, 0, 0}, y = {0, -1, 0};
      break;
    case UpAxis::PosZ:
      x = {1, 0, 0}, y = {0, 0, 1};
      break;
    case UpAxis::NegZ:
      x = {1, 0, 0}, y = {0, 0, -1};
      break;
    case UpAxis::PosX:
      x = {0, -1, 0}, y = {1, 0, 0};
      break;
    case UpAxis::NegX:
      x = {0, 1, 0}, y = {-1, 0, 0};
      break;
  }
  Eigen::Matrix3d m;
  m << x, y, x.cross(y);
  return m;
}

/// The camera frame of the options in world coordinates: the named view, turned by azimuth
/// about the view frame's up axis and raised by elevation about the camera's right axis, then
/// carried to the world by the up axis.
CameraFrame camera_frame(const RenderOptions& o) {
  CameraFrame c = view_frame(o.view);
  const double deg = M_PI / 180.0;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(o.azimuth_deg * deg, Eigen::Vector3d::UnitY()).toRotationMatrix();
  c.right = turn * c.right;
  c.up = turn * c.up;
  c.back = turn * c.back;
  // A positive rotation about `right` moves `back` away from `up`: raise by −elevation.
  const Eigen::Matrix3d raise = Eigen::AngleAxisd(-o.elevation_deg * deg, c.right).toRotationMatrix();
  c.up = raise * c.up;
  c.back = raise * c.back;
  const Eigen::Matrix3d world = up_axis_frame(o.up);
  c.right = world * c.right;
  c.up = world * c.up;
  c.back = world * c.back;
  return c;
}

/// Maps world points to supersampled screen coordinates (x right, y down, in samples) and a
/// depth key q that grows towards the viewer and is affine in screen space (the camera z for
/// the orthographic camera, 1/distance for the perspective one), so it interpolates linearly.
struct Projector {
  CameraFrame frame;
  bool perspective = false;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double distance = 1;               // perspective: eye = center + back·distance
  double scale = 1, cx = 0, cy = 0;  // screen = (W/2 + scale (x − cx), H/2 − scale (y − cy))
  double half_w = 0, half_h = 0;

  // Camera-plane coordinates before scaling, and the depth key.
  Eigen::Vector3d camera(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - center;
    const double x = frame.right.dot(d), y = frame.up.dot(d), z = frame.back.dot(d);
    if (!perspective) return {x, y, z};
    const double dist = distance - z;  // > 0 for every point inside the framed sphere
    if (!(dist > 1e-9 * distance)) return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    return {x / dist, y / dist, 1.0 / dist};
  }
  Eigen::Vector3d screen(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d c = camera(p);
    return {half_w + scale * (c.x() - cx), half_h - scale * (c.y() - cy), c.z()};
  }
};

/// Fits the points P (#P by 3, at least one) into the picture: exact extents of their
/// projections, so the framing is tight whatever the view.
Projector make_projector(const Eigen::MatrixXd& P, const RenderOptions& o) {
  Projector p;
  p.frame = camera_frame(o);
  p.perspective = o.projection == Projection::Perspective;
  const Eigen::Vector3d lo = P.colwise().minCoeff().transpose(), hi = P.colwise().maxCoeff().transpose();
  p.center = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 1e-300);
  // The whole bounding sphere stays in front of the eye; the field of view sets the distance
  // (how strong the perspective is), the fit below sets the zoom.
  p.distance = radius / std::sin(0.5 * o.fov_deg * M_PI / 180.0);
  const int ss = o.supersample;
  const double W = double(o.width) * ss, H = double(o.height) * ss;
  p.half_w = 0.5 * W;
  p.half_h = 0.5 * H;
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    const Eigen::Vector3d c = p.camera(P.row(i).transpose());
    xmin = std::min(xmin, c.x());
    xmax = std::max(xmax, c.x());
    ymin = std::min(ymin, c.y());
    ymax = std::max(ymax, c.y());
  }
  p.cx = 0.5 * (xmin + xmax);
  p.cy = 0.5 * (ymin + ymax);
  const double sx = W * (1 - 2 * o.margin) / std::max(xmax - xmin, 1e-300);
  const double sy = H * (1 - 2 * o.margin) / std::max(ymax - ymin, 1e-300);
  p.scale = std::min(sx, sy);
  if (!std::isfinite(p.scale) || !(p.scale > 0)) p.scale = 1;  // a single point: any zoom
  return p;
}

inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// ---- the steps of render_mesh ----

/// Throws InvalidInput when the style's arrays do not fit a mesh of nf faces.
void check_style(const MeshStyle& style, Eigen::Index nf, Eigen::Index nv) {
  if (style.face_colors.size() != 0 && (style.face_colors.rows() != nf || style.face_colors.cols() != 3))
    throw InvalidInput("render: face_colors is " + std::to_string(style.face_colors.rows()) + "x" +
                       std::to_string(style.face_colors.cols()) + ", expected " + std::to_string(nf) + "x3");
  if (style.vertex_colors.size() != 0) {
    if (style.face_colors.size() != 0) throw InvalidInput("render: give face_colors or vertex_colors, not both");
    if (style.vertex_colors.rows() != nv || style.vertex_colors.cols() != 3)
      throw InvalidInput("render: vertex_colors is " + std::to_string(style.vertex_colors.rows()) + "x" +
                         std::to_string(style.vertex_colors.cols()) + ", expected " + std::to_string(nv) + "x3");
    if (!style.vertex_colors.allFinite()) throw InvalidInput("render: vertex_colors must be finite");
  }
  if (style.lines.size() != 0 && style.lines.cols() != 2)
    throw InvalidInput("render: lines must have 2 columns (vertex pairs)");
  const Eigen::Index nl = style.lines.rows();
  if (style.line_colors.size() != 0 &&
      ((style.line_colors.rows() != nl && style.line_colors.rows() != 1) || style.line_colors.cols() != 3))
    throw InvalidInput("render: line_colors is " + std::to_string(style.line_colors.rows()) + "x" +
                       std::to_string(style.line_colors.cols()) + ", expected " + std::to_string(nl) + "x3 or 1x3");
}

/// Camera setup: frames the given points, or the vertices the faces use.
Projector frame_camera(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const RenderOptions& o) {
  Eigen::MatrixXd used;
  if (o.frame_points.rows() == 0) {
    std::vector<bool> is_used(V.rows(), false);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) is_used[F(f, k)] = true;
    used.resize(std::count(is_used.begin(), is_used.end(), true), 3);
    Eigen::Index r = 0;
    for (Eigen::Index i = 0; i < V.rows(); ++i)
      if (is_used[i]) used.row(r++) = V.row(i);
  }
  return make_projector(o.frame_points.rows() ? o.frame_points : used, o);
}

/// Lines, by vertex: a face draws the lines at any of its corners, so that a line is
/// continuous also where the faces along it meet it only at a vertex (there the face with the
/// edge does not cover the whole half-width around the line). Empty without lines; throws
/// InvalidInput for a line that is not an edge of F.
std::vector<std::vector<int>> lines_by_vertex(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                              const MeshStyle& style) {
  std::vector<std::vector<int>> vertex_lines;
  const Eigen::Index nf = F.rows(), nl = style.lines.rows();
  if (nl == 0) return vertex_lines;
  std::unordered_set<std::uint64_t> edges;
  edges.reserve(static_cast<size_t>(nf) * 3);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) edges.insert(edge_key(F(f, k), F(f, (k + 1) % 3)));
  vertex_lines.resize(static_cast<size_t>(V.rows()));
  for (Eigen::Index l = 0; l < nl; ++l) {
    const int a = style.lines(l, 0), b = style.lines(l, 1);
    if (a < 0 || b < 0 || a >= V.rows() || b >= V.rows() || !edges.count(edge_key(a, b)))
      throw InvalidInput("render: line " + std::to_string(l) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") is not an edge of the mesh");
    vertex_lines[a].push_back(static_cast<int>(l));
    vertex_lines[b].push_back(static_cast<int>(l));
  }
  return vertex_lines;
}

/// The lines face f may show: those at its corners (unique) whose ends are on screen.
std::vector<int> lines_at_face(const Eigen::MatrixXi& F, Eigen::Index f,
                               const std::vector<std::vector<int>>& vertex_lines, const std::vector<Eigen::Vector3d>& S,
                               const MeshStyle& style) {
  std::vector<int> lines_here;
  if (vertex_lines.empty()) return lines_here;
  for (int k = 0; k < 3; ++k)
    for (int l : vertex_lines[F(f, k)])
      if (std::find(lines_here.begin(), lines_here.end(), l) == lines_here.end() && S[style.lines(l, 0)].allFinite() &&
          S[style.lines(l, 1)].allFinite())
        lines_here.push_back(l);
  return lines_here;
}

Eigen::Vector3f line_color(const MeshStyle& style, int l) {
  if (style.line_colors.rows() == 0) return Eigen::Vector3f::Zero();
  return style.line_colors.row(style.line_colors.rows() == 1 ? 0 : l).transpose().cast<float>();
}

/// The colours of a face's three corners (equal unless vertex colours are given).
struct CornerColors {
  Eigen::Vector3f c[3];
  bool uniform = true;
};

/// Colouring: the face's colour (style, vertex colours or base colour) under flat Lambert
/// shading, lit on the side facing the viewer. `light`: unit light direction in camera
/// coordinates; `eye`: the perspective eye.
CornerColors shaded_face_colors(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index f,
                                const MeshStyle& style, const RenderOptions& o, const Projector& proj,
                                const Eigen::Vector3d& light, const Eigen::Vector3d& eye) {
  const Eigen::Vector3d p0 = V.row(F(f, 0)).transpose(), p1 = V.row(F(f, 1)).transpose(),
                        p2 = V.row(F(f, 2)).transpose();
  Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
  const double nn = n.norm();
  double shade = o.ambient + o.diffuse;  // a zero-area face has no normal: full light
  if (nn > 0) {
    n /= nn;
    const Eigen::Vector3d to_viewer = proj.perspective ? Eigen::Vector3d(eye - (p0 + p1 + p2) / 3.0) : proj.frame.back;
    if (n.dot(to_viewer) < 0) n = -n;
    const Eigen::Vector3d nc(proj.frame.right.dot(n), proj.frame.up.dot(n), proj.frame.back.dot(n));
    shade = o.ambient + o.diffuse * std::max(0.0, nc.dot(light));
  }
  CornerColors out;
  if (style.vertex_colors.rows()) {
    for (int k = 0; k < 3; ++k)
      out.c[k] = (Eigen::Vector3d(style.vertex_colors.row(F(f, k)).transpose()) * shade)
                     .cwiseMin(1.0)
                     .cwiseMax(0.0)
                     .cast<float>();
    out.uniform = out.c[0] == out.c[1] && out.c[1] == out.c[2];
    return out;
  }
  const Eigen::Vector3d base =
      style.face_colors.rows() ? Eigen::Vector3d(style.face_colors.row(f).transpose()) : o.base_color;
  out.c[0] = out.c[1] = out.c[2] = (base * shade).cwiseMin(1.0).cwiseMax(0.0).cast<float>();
  return out;
}

/// The supersampled picture being drawn: colour and depth key per sample.
struct SampleBuffer {
  int W = 0, H = 0;
  std::vector<Eigen::Vector3f> color;
  std::vector<double> depth;
  SampleBuffer(int w, int h, const Eigen::Vector3d& background)
      : W(w),
        H(h),
        color(static_cast<size_t>(w) * h, background.cast<float>()),
        depth(static_cast<size_t>(w) * h, -std::numeric_limits<double>::infinity()) {}
};

/// Twice the signed screen area of the triangle s; both orientations are drawn (faces are
/// two-sided).
double twice_screen_area(const Eigen::Vector3d s[3]) {
  return (s[1].x() - s[0].x()) * (s[2].y() - s[0].y()) - (s[2].x() - s[0].x()) * (s[1].y() - s[0].y());
}

/// Rasterising: z-tested samples of the screen triangle s (twice its signed area: area2) get
/// the face's colour (interpolated between its corners), or the colour of the nearest of `lines` (screen segments
/// between the points S) within half_line samples.
void rasterise_face(SampleBuffer& buf, const Eigen::Vector3d s[3], double area2, const CornerColors& face_color,
                    const std::vector<int>& lines, const std::vector<Eigen::Vector3d>& S, const MeshStyle& style,
                    double half_line) {
  const int W = buf.W, H = buf.H;
  const double xmin = std::min({s[0].x(), s[1].x(), s[2].x()}), xmax = std::max({s[0].x(), s[1].x(), s[2].x()});
  const double ymin = std::min({s[0].y(), s[1].y(), s[2].y()}), ymax = std::max({s[0].y(), s[1].y(), s[2].y()});
  const int x0 = std::max(0, static_cast<int>(std::floor(xmin - 0.5))),
            x1 = std::min(W - 1, static_cast<int>(std::ceil(xmax - 0.5)));
  const int y0 = std::max(0, static_cast<int>(std::floor(ymin - 0.5))),
            y1 = std::min(H - 1, static_cast<int>(std::ceil(ymax - 0.5)));
  const double inv = 1.0 / area2;
  // Samples exactly on a shared edge belong to both faces (the z-test picks one): no cracks.
  const double tol = -1e-9;
  for (int y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      // Barycentric coordinate k: signed area of the sub-triangle opposite corner k.
      const double w0 = ((s[1].x() - px) * (s[2].y() - py) - (s[2].x() - px) * (s[1].y() - py)) * inv;
      const double w1 = ((s[2].x() - px) * (s[0].y() - py) - (s[0].x() - px) * (s[2].y() - py)) * inv;
      const double w2 = 1.0 - w0 - w1;
      if (w0 < tol || w1 < tol || w2 < tol) continue;
      const double q = w0 * s[0].z() + w1 * s[1].z() + w2 * s[2].z();
      const size_t idx = static_cast<size_t>(y) * W + x;
      if (!(q > buf.depth[idx])) continue;
      buf.depth[idx] = q;
      Eigen::Vector3f c = face_color.uniform
                              ? face_color.c[0]
                              : Eigen::Vector3f(float(w0) * face_color.c[0] + float(w1) * face_color.c[1] +
                                                float(w2) * face_color.c[2]);
      // The nearest line within half the line width colours the sample (distance to the
      // segment, in samples: round ends).
      double best = half_line;
      for (int l : lines) {
        const Eigen::Vector3d& a = S[style.lines(l, 0)];
        const Eigen::Vector3d& b = S[style.lines(l, 1)];
        const double dx = b.x() - a.x(), dy = b.y() - a.y(), len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(((px - a.x()) * dx + (py - a.y()) * dy) / len2, 0.0, 1.0) : 0.0;
        const double dist = std::hypot(px - (a.x() + t * dx), py - (a.y() + t * dy));
        if (dist < best) {
          best = dist;
          c = line_color(style, l);
        }
      }
      buf.color[idx] = c;
    }
  }
}

/// Box filter of the s×s samples of each pixel down to the output size.
Image downsample(const SampleBuffer& buf, const RenderOptions& o) {
  const int ss = o.supersample;
  Image out(o.width, o.height);
  const float norm = 1.0f / float(ss * ss);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      Eigen::Vector3f sum = Eigen::Vector3f::Zero();
      for (int j = 0; j < ss; ++j)
        for (int i = 0; i < ss; ++i) sum += buf.color[static_cast<size_t>(y * ss + j) * buf.W + (x * ss + i)];
      out.set(x, y, (sum * norm).cast<double>());
    }
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Rasteriser
// ---------------------------------------------------------------------------------------

Image render_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const MeshStyle& style, const RenderOptions& o) {
  o.validate();
  validate_mesh(V, F, "render");
  const Eigen::Index nf = F.rows();
  check_style(style, nf, V.rows());
  if (nf == 0) return Image(o.width, o.height, o.background);

  const int ss = o.supersample;
  SampleBuffer buf(o.width * ss, o.height * ss, o.background);
  const Projector proj = frame_camera(V, F, o);
  // Screen positions of the vertices (samples; NaN behind a perspective eye).
  std::vector<Eigen::Vector3d> S(static_cast<size_t>(V.rows()));
  for (Eigen::Index i = 0; i < V.rows(); ++i) S[i] = proj.screen(V.row(i).transpose());
  const std::vector<std::vector<int>> vertex_lines = lines_by_vertex(V, F, style);

  const Eigen::Vector3d light = o.light.normalized();
  const double half_line = 0.5 * o.line_width * ss;  // in samples
  const Eigen::Vector3d eye = proj.center + proj.frame.back * proj.distance;
  for (Eigen::Index f = 0; f < nf; ++f) {
    const Eigen::Vector3d s[3] = {S[F(f, 0)], S[F(f, 1)], S[F(f, 2)]};
    if (!s[0].allFinite() || !s[1].allFinite() || !s[2].allFinite()) continue;  // behind the eye (not clipped)
    const double area2 = twice_screen_area(s);
    if (!(std::abs(area2) > 1e-12)) continue;  // seen edge-on or degenerate: covers nothing
    rasterise_face(buf, s, area2, shaded_face_colors(V, F, f, style, o, proj, light, eye),
                   lines_at_face(F, f, vertex_lines, S, style), S, style, half_line);
  }
  return downsample(buf, o);
}

Eigen::MatrixXi sharp_edges(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double angle_deg, bool boundary) {
  validate_mesh(V, F, "sharp_edges");
  if (!(angle_deg >= 0 && angle_deg <= 180))
    throw InvalidInput("sharp_edges: angle " + std::to_string(angle_deg) + " is outside [0, 180] degrees");
  const Topology topo = build_topology(F, V.rows());
  const Eigen::VectorXd dihedral = dihedral_angles(V, F, topo);
  const double threshold = angle_deg * M_PI / 180.0;
  std::vector<int> keep;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    const bool is_boundary = topo.edge_face_count(e) == 1;
    if ((topo.edge_is_interior[e] && dihedral(e) > threshold) || (boundary && is_boundary))
      keep.push_back(static_cast<int>(e));
  }
  Eigen::MatrixXi L(static_cast<Eigen::Index>(keep.size()), 2);
  for (size_t i = 0; i < keep.size(); ++i) L.row(i) = topo.edges.row(keep[i]);
  return L;
}

}  // namespace msmesh
