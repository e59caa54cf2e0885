// render.h: the rasteriser against known pixels of simple scenes (the CLI's render, compare
// and --report outputs: cli/test_render_cli.cpp). The other headers of the drawing library
// have their own tests (test_image, test_color_map, test_text, test_color_bar, test_png).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "image_test_helpers.h"
#include "msmesh/errors.h"
#include "msmesh/image.h"
#include "msmesh/io.h"
#include "msmesh/png.h"
#include "msmesh/render.h"
#include "test_helpers.h"

using namespace msmesh;
namespace fs = std::filesystem;

namespace {

/// One big triangle in the plane z = 0, counter-clockwise seen from +z (the front view).
Mesh big_triangle(double z = 0) {
  Mesh m;
  m.V.resize(3, 3);
  m.V << -1, -1, z, 1, -1, z, 0, 1, z;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  return m;
}

/// The axis-aligned cube [-1,1]³, two triangles per side, outward.
Mesh cube() {
  Mesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) m.V.row(i) << ((i & 1) ? 1 : -1), ((i & 2) ? 1 : -1), ((i & 4) ? 1 : -1);
  m.F.resize(12, 3);
  m.F << 0, 2, 3, 0, 3, 1,  // z = -1
      4, 5, 7, 4, 7, 6,     // z = +1
      0, 1, 5, 0, 5, 4,     // y = -1
      2, 6, 7, 2, 7, 3,     // y = +1
      0, 4, 6, 0, 6, 2,     // x = -1
      1, 3, 7, 1, 7, 5;     // x = +1
  return m;
}

/// The byte the rasteriser should write for a face of colour c and normal n (camera space).
int expected_byte(double c, const Eigen::Vector3d& n_camera, const RenderOptions& o) {
  const double shade = o.ambient + o.diffuse * std::max(0.0, n_camera.dot(o.light.normalized()));
  return static_cast<int>(std::lround(std::min(1.0, c * shade) * 255));
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Rasteriser
// ---------------------------------------------------------------------------------------

TEST(Render, TriangleFacingTheCameraHasTheExpectedShadeAndWhiteCorners) {
  const Mesh m = big_triangle();
  RenderOptions o;
  o.width = 64;
  o.height = 48;
  o.view = View::Front;
  const Image im = render_mesh(m.V, m.F, {}, o);
  ASSERT_EQ(im.width, 64);
  ASSERT_EQ(im.height, 48);
  ASSERT_EQ(im.rgb.size(), 64u * 48u * 3u);
  // Front view: camera space normal (0, 0, 1); light grey base colour.
  const int e = expected_byte(o.base_color(0), Eigen::Vector3d(0, 0, 1), o);
  for (int k : test::px(im, 32, 24)) EXPECT_EQ(k, e);
  for (auto [x, y] : {std::pair{0, 0}, {63, 0}, {0, 47}, {63, 47}})
    for (int k : test::px(im, x, y)) EXPECT_EQ(k, 255) << "corner " << x << "," << y;
  // The apex is at the top centre: the top row is white away from the middle.
  for (int k : test::px(im, 10, 3)) EXPECT_EQ(k, 255);
}

TEST(Render, BackSideIsLitLikeTheFront) {
  Mesh m = big_triangle();
  m.F << 0, 2, 1;  // facing away from the camera
  RenderOptions o;
  o.width = o.height = 32;
  o.view = View::Front;
  const Image a = render_mesh(m.V, m.F, {}, o);
  const Image b = render_mesh(big_triangle().V, big_triangle().F, {}, o);
  EXPECT_EQ(test::px(a, 16, 16), test::px(b, 16, 16));
}

TEST(Render, ZBufferKeepsTheNearestFaceWhateverTheOrder) {
  // Two triangles, the one at z = 0.5 (nearer the front camera) red, the other blue.
  Mesh m;
  m.V.resize(6, 3);
  m.V << -1, -1, 0, 1, -1, 0, 0, 1, 0, -1, -1, 0.5, 1, -1, 0.5, 0, 1, 0.5;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 3, 4, 5;
  MeshStyle s;
  s.face_colors.resize(2, 3);
  s.face_colors << 0, 0, 1, 1, 0, 0;
  RenderOptions o;
  o.width = o.height = 40;
  o.view = View::Front;
  const Image a = render_mesh(m.V, m.F, s, o);
  Eigen::MatrixXi F2 = m.F.colwise().reverse();
  MeshStyle s2 = s;
  s2.face_colors = s.face_colors.colwise().reverse();
  const Image b = render_mesh(m.V, F2, s2, o);
  const auto c = test::px(a, 20, 20);
  EXPECT_GT(c[0], 100);
  EXPECT_EQ(c[2], 0);
  EXPECT_EQ(c, test::px(b, 20, 20));
  // Seen from the back, the blue one is in front.
  o.view = View::Back;
  const auto d = test::px(render_mesh(m.V, m.F, s, o), 20, 20);
  EXPECT_EQ(d[0], 0);
  EXPECT_GT(d[2], 100);
}

TEST(Render, CubeIsoViewShowsThreeDistinctShades) {
  const Mesh m = cube();
  RenderOptions o;
  o.width = o.height = 120;
  o.view = View::Iso;
  const Image im = render_mesh(m.V, m.F, {}, o);
  std::map<std::array<int, 3>, int> histogram;
  int covered = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const auto c = test::px(im, x, y);
      if (c == std::array<int, 3>{255, 255, 255}) continue;
      ++covered;
      ++histogram[c];
    }
  ASSERT_GT(covered, 0.3 * im.width * im.height);
  std::vector<std::pair<int, std::array<int, 3>>> big;
  for (const auto& [c, n] : histogram)
    if (n > 0.15 * covered) big.push_back({n, c});
  ASSERT_EQ(big.size(), 3u) << "three faces of the cube, each with its own flat shade";
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = i + 1; j < 3; ++j) EXPECT_GT(std::abs(big[i].second[0] - big[j].second[0]), 8);
  // The top face (+y) is in the upper middle of the picture and the brightest (light from above).
  const auto top = test::px(im, 60, 30);
  for (const auto& b : big) EXPECT_GE(top[0], b.second[0]);
  // The expected shade of the top face: its camera-space normal is (0, up·y, back·y).
  const Eigen::Vector3d back = Eigen::Vector3d(1, 1, 1).normalized();
  const Eigen::Vector3d up = (Eigen::Vector3d(0, 1, 0) - back * back.y()).normalized();
  EXPECT_EQ(top[0], expected_byte(o.base_color(0), Eigen::Vector3d(0, up.y(), back.y()), o));
}

TEST(Render, IsDeterministic) {
  const Mesh m = test::grid(12, 0.3);
  RenderOptions o;
  o.width = 90;
  o.height = 70;
  o.projection = Projection::Perspective;
  MeshStyle s;
  s.lines = sharp_edges(m.V, m.F, 0, true);
  s.line_colors = Eigen::RowVector3d(0.2, 0.1, 0.0);
  const Image a = render_mesh(m.V, m.F, s, o), b = render_mesh(m.V, m.F, s, o);
  EXPECT_TRUE(a == b);
  EXPECT_EQ(encode_png(a), encode_png(b));
}

TEST(Render, ViewsFrameTheMeshInsideTheMargin) {
  const Mesh m = cube();
  for (const std::string& name : view_names()) {
    RenderOptions o;
    o.width = 80;
    o.height = 60;
    o.view = view_from_name(name);
    for (Projection p : {Projection::Orthographic, Projection::Perspective}) {
      o.projection = p;
      const Image im = render_mesh(m.V, m.F, {}, o);
      int xmin = im.width, xmax = -1, ymin = im.height, ymax = -1;
      for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
          if (test::px(im, x, y) != std::array<int, 3>{255, 255, 255}) {
            xmin = std::min(xmin, x);
            xmax = std::max(xmax, x);
            ymin = std::min(ymin, y);
            ymax = std::max(ymax, y);
          }
      ASSERT_GE(xmax, 0) << name << ": nothing drawn";
      // Inside the 5% margin, touching it on the tighter axis, centred.
      EXPECT_GE(xmin, 3) << name;
      EXPECT_LE(xmax, 76) << name;
      EXPECT_GE(ymin, 2) << name;
      EXPECT_LE(ymax, 57) << name;
      EXPECT_TRUE(ymin <= 4 || xmin <= 5) << name << ": the picture should be filled along one axis";
      EXPECT_LE(std::abs((xmin + xmax) - 79), 3) << name;
      EXPECT_LE(std::abs((ymin + ymax) - 59), 3) << name;
    }
  }
}

TEST(Render, LinesAreDrawnOnTheirEdgeOnly) {
  const Mesh m = big_triangle();
  MeshStyle s;
  s.lines.resize(1, 2);
  s.lines << 0, 1;  // the bottom edge
  s.line_colors = Eigen::RowVector3d(0, 0, 0);
  RenderOptions o;
  o.width = o.height = 100;
  o.view = View::Front;
  o.line_width = 4;
  const Image im = render_mesh(m.V, m.F, s, o);
  // The bottom edge is at y = 95 (5% margin): a dark line just above it; the centre is grey.
  int darkest = 255;
  for (int y = 90; y < 96; ++y) darkest = std::min(darkest, test::px(im, 50, y)[0]);
  EXPECT_LT(darkest, 40);
  EXPECT_GT(test::px(im, 50, 50)[0], 150);
  s.lines << 0, 5;
  EXPECT_THROW(render_mesh(m.V, m.F, s, o), InvalidInput);
}

TEST(Render, FramePointsGiveTheSameScaleToSeveralMeshes) {
  const Mesh big = big_triangle();
  Mesh small = big;
  small.V *= 0.5;
  RenderOptions o;
  o.width = o.height = 50;
  o.view = View::Front;
  o.frame_points = big.V;
  const Image a = render_mesh(small.V, small.F, {}, o);
  o.frame_points.resize(0, 3);  // framed by itself: as large as the big one
  const Image b = render_mesh(small.V, small.F, {}, o);
  auto coverage = [](const Image& im) {
    int n = 0;
    for (size_t i = 0; i < im.rgb.size(); i += 3) n += im.rgb[i] != 255;
    return n;
  };
  EXPECT_NEAR(4.0 * coverage(a), coverage(b), 0.1 * coverage(b)) << "half the size: a quarter of the pixels";
}

TEST(Render, RejectsBadInput) {
  const Mesh m = big_triangle();
  RenderOptions o;
  o.width = 0;
  EXPECT_THROW(render_mesh(m.V, m.F, {}, o), InvalidInput);
  o = {};
  o.supersample = 9;
  EXPECT_THROW(o.validate(), InvalidInput);
  EXPECT_THROW(view_from_name("sideways"), InvalidInput);
  MeshStyle s;
  s.face_colors = Eigen::MatrixXd::Zero(2, 3);
  EXPECT_THROW(render_mesh(m.V, m.F, s, {}), InvalidInput);
  Eigen::MatrixXi badF(1, 3);
  badF << 0, 1, 7;
  EXPECT_THROW(render_mesh(m.V, badF, {}, {}), InvalidInput);
  // No faces: the background.
  const Image empty = render_mesh(m.V, Eigen::MatrixXi(0, 3), {}, RenderOptions{});
  EXPECT_TRUE(std::all_of(empty.rgb.begin(), empty.rgb.end(), [](std::uint8_t b) { return b == 255; }));
}

TEST(Render, SharpEdgesOfACubeAreItsTwelveEdges) {
  const Mesh m = cube();
  EXPECT_EQ(sharp_edges(m.V, m.F, 30).rows(), 12);
  EXPECT_EQ(sharp_edges(m.V, m.F, 95).rows(), 0);
  const Mesh g = test::grid(2);
  EXPECT_EQ(sharp_edges(g.V, g.F, 10, true).rows(), 8);  // the boundary of a flat 2×2 grid
}

// ---------------------------------------------------------------------------------------
// Up axis, camera angles and vertex colours
// ---------------------------------------------------------------------------------------

namespace {

/// The bounding box of the pixels that are not white: {xmin, xmax, ymin, ymax}.
std::array<int, 4> drawn_box(const Image& im) {
  std::array<int, 4> b{im.width, -1, im.height, -1};
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      if (test::px(im, x, y) != std::array<int, 3>{255, 255, 255}) {
        b[0] = std::min(b[0], x);
        b[1] = std::max(b[1], x);
        b[2] = std::min(b[2], y);
        b[3] = std::max(b[3], y);
      }
  return b;
}

/// The mean absolute difference of two images' bytes.
double mean_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
  return sum / double(a.rgb.size());
}

/// A triangle standing in the plane y = 0 with its apex at +z: upright for a Z-up scan.
Mesh z_up_triangle() {
  Mesh m;
  m.V.resize(3, 3);
  m.V << -1, 0, -1, 1, 0, -1, 0, 0, 1;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  return m;
}

/// Width of the drawn pixels on row y.
int row_width(const Image& im, int y) {
  int n = 0;
  for (int x = 0; x < im.width; ++x) n += test::px(im, x, y) != std::array<int, 3>{255, 255, 255};
  return n;
}

}  // namespace

TEST(Render, UpAxisShowsAZUpMeshUpright) {
  const Mesh m = z_up_triangle();
  RenderOptions o;
  o.width = o.height = 80;
  o.view = View::Front;
  o.up = UpAxis::PosZ;  // front looks from -y: the triangle faces the camera, apex up
  Image im = render_mesh(m.V, m.F, {}, o);
  std::array<int, 4> b = drawn_box(im);
  ASSERT_GE(b[1], 0) << "nothing drawn";
  EXPECT_LT(row_width(im, b[2] + 2), row_width(im, b[3] - 2) / 4) << "apex at the top";
  o.up = UpAxis::NegZ;  // upside down
  im = render_mesh(m.V, m.F, {}, o);
  b = drawn_box(im);
  EXPECT_GT(row_width(im, b[2] + 2), 4 * row_width(im, b[3] - 2)) << "apex at the bottom";
  o.up = UpAxis::PosY;  // the default looks from +z: the triangle is seen edge-on
  im = render_mesh(m.V, m.F, {}, o);
  b = drawn_box(im);
  EXPECT_LE(b[3] - b[2], 3) << "edge-on: a line at most";
}

TEST(Render, UpAxesAreRotationsThatKeepTheViewsApart) {
  // A box longer along the up axis than across it is drawn taller than wide from the side,
  // whichever axis is up.
  for (const std::string& name : up_axis_names()) {
    const UpAxis up = up_axis_from_name(name);
    Mesh box = cube();
    const int axis = (name.back() == 'x') ? 0 : (name.back() == 'y') ? 1 : 2;
    for (int k = 0; k < 3; ++k)
      if (k != axis) box.V.col(k) *= 0.3;
    RenderOptions o;
    o.width = o.height = 60;
    o.up = up;
    for (View v : {View::Front, View::Right, View::Iso}) {
      o.view = v;
      const std::array<int, 4> b = drawn_box(render_mesh(box.V, box.F, {}, o));
      EXPECT_GT(b[3] - b[2], 2 * (b[1] - b[0])) << "up " << name << ", view " << int(v);
    }
    o.view = View::Top;  // seen along the up axis: a small square
    const std::array<int, 4> b = drawn_box(render_mesh(box.V, box.F, {}, o));
    EXPECT_LE(std::abs((b[3] - b[2]) - (b[1] - b[0])), 2) << "up " << name;
    EXPECT_EQ(up_axis_name(up), name);
  }
  EXPECT_EQ(up_axis_from_name("+z"), UpAxis::PosZ);
  EXPECT_THROW(up_axis_from_name("w"), InvalidInput);
}

TEST(Render, AzimuthAndElevationTurnTheNamedViews) {
  // An asymmetric shape so that every view differs.
  Mesh m = cube();
  m.V.col(0) *= 1.6;
  m.V(7, 1) += 0.7;
  for (UpAxis up : {UpAxis::PosY, UpAxis::PosZ}) {
    RenderOptions o;
    o.width = o.height = 64;
    o.up = up;
    o.view = View::Right;
    const Image right = render_mesh(m.V, m.F, {}, o);
    o.view = View::Top;
    const Image top = render_mesh(m.V, m.F, {}, o);
    o.view = View::Front;
    const Image front = render_mesh(m.V, m.F, {}, o);
    o.azimuth_deg = 90;  // front turned by 90° is the right view
    const Image turned = render_mesh(m.V, m.F, {}, o);
    EXPECT_LT(mean_difference(turned, right), 0.5);
    EXPECT_GT(mean_difference(turned, front), 5.0);
    o.azimuth_deg = 0;
    o.elevation_deg = 90;  // front raised by 90° is the top view
    EXPECT_LT(mean_difference(render_mesh(m.V, m.F, {}, o), top), 0.5);
    o.elevation_deg = 30;
    const Image raised = render_mesh(m.V, m.F, {}, o);
    EXPECT_GT(mean_difference(raised, front), 2.0);
    EXPECT_GT(mean_difference(raised, top), 2.0);
  }
  RenderOptions o;
  o.elevation_deg = 91;
  EXPECT_THROW(o.validate(), InvalidInput);
  o.elevation_deg = 0;
  o.azimuth_deg = 400;
  EXPECT_THROW(o.validate(), InvalidInput);
}

TEST(Render, VertexColorsAreInterpolatedAndShaded) {
  const Mesh m = big_triangle();
  MeshStyle s;
  s.vertex_colors.resize(3, 3);
  s.vertex_colors << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  RenderOptions o;
  o.width = o.height = 100;
  o.view = View::Front;
  o.supersample = 1;
  const Image im = render_mesh(m.V, m.F, s, o);
  // Near each corner its own colour dominates (bottom left red, bottom right green, apex blue).
  const auto bl = test::px(im, 12, 92), br = test::px(im, 87, 92), apex = test::px(im, 50, 10);
  EXPECT_GT(bl[0], 3 * std::max(bl[1], bl[2]) + 10);
  EXPECT_GT(br[1], 3 * std::max(br[0], br[2]) + 10);
  EXPECT_GT(apex[2], 3 * std::max(apex[0], apex[1]) + 10);
  // The centroid mixes the three equally, under the face's shade.
  const auto c = test::px(im, 50, 63);
  EXPECT_LE(std::abs(c[0] - c[1]), 12);
  EXPECT_LE(std::abs(c[1] - c[2]), 12);
  // One colour everywhere gives the same pixels as that face colour.
  MeshStyle grey, faces;
  grey.vertex_colors = Eigen::MatrixXd::Constant(3, 3, 0.6);
  faces.face_colors = Eigen::MatrixXd::Constant(1, 3, 0.6);
  EXPECT_EQ(render_mesh(m.V, m.F, grey, o), render_mesh(m.V, m.F, faces, o));
  // Wrong sizes, or both kinds at once, are refused.
  MeshStyle bad;
  bad.vertex_colors = Eigen::MatrixXd::Zero(2, 3);
  EXPECT_THROW(render_mesh(m.V, m.F, bad, o), InvalidInput);
  bad.vertex_colors = Eigen::MatrixXd::Zero(3, 3);
  bad.face_colors = Eigen::MatrixXd::Zero(1, 3);
  EXPECT_THROW(render_mesh(m.V, m.F, bad, o), InvalidInput);
}
