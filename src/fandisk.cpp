// The CAD-like part make_fandisk_like (shapes.h): a planar profile of lines and one arc,
// extruded along z, meshed patch by patch (patch_mesher.h).
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "msmesh/shapes.h"
#include "patch_mesher.h"
#include "shape_builder.h"

namespace msmesh {

using namespace detail;

namespace {

/// Translates V (#V by 3) so that its bounding box is centred at the origin.
void centre_bounding_box(Eigen::MatrixXd& V) {
  const Eigen::RowVector3d c = 0.5 * (V.colwise().minCoeff() + V.colwise().maxCoeff());
  V.rowwise() -= c;
}

// The CAD-like part: a planar profile of lines and arcs, extruded along z.

/// A straight segment or circular arc of a planar profile, parametrised by t ∈ [0,1].
struct ProfileSegment {
  Vec2 a, b;  ///< end points
  bool is_arc = false;
  Vec2 centre = Vec2::Zero();  ///< arc: centre + radius (cos, sin)(angle0 + t sweep)
  double radius = 0, angle0 = 0, sweep = 0;

  double length() const { return is_arc ? radius * std::abs(sweep) : (b - a).norm(); }
  Vec2 at(double t) const {
    if (!is_arc) return a + t * (b - a);
    const double angle = angle0 + t * sweep;
    return centre + radius * Vec2(std::cos(angle), std::sin(angle));
  }
  /// Arc length from a to p, for p on the segment.
  double arclength(const Vec2& p) const {
    if (!is_arc) return (p - a).dot((b - a).normalized());
    const Vec2 d = p - centre;
    const double turned = std::remainder(std::atan2(d.y(), d.x()) - angle0, 2 * kPi);
    return length() * turned / sweep;
  }
};

/// Draws a profile as a turtle: lines, turns and tangent arcs (degrees, positive = left).
class Turtle {
 public:
  Vec2 position() const { return position_; }
  void turn(double degrees) { heading_ += degrees * kPi / 180; }
  void line(double length) {
    ProfileSegment s;
    s.a = position_;
    s.b = position_ + length * Vec2(std::cos(heading_), std::sin(heading_));
    segments_.push_back(s);
    position_ = s.b;
  }
  /// An arc tangent to the current heading, turning by `degrees` (left when positive).
  void arc(double radius, double degrees) {
    const double sweep = degrees * kPi / 180, side = sweep > 0 ? 1.0 : -1.0;
    ProfileSegment s;
    s.is_arc = true;
    s.a = position_;
    s.radius = radius;
    s.centre = position_ + side * radius * Vec2(-std::sin(heading_), std::cos(heading_));
    s.angle0 = heading_ - side * kPi / 2;
    s.sweep = sweep;
    s.b = s.at(1.0);
    segments_.push_back(s);
    position_ = s.b;
    heading_ += sweep;
  }
  /// Ends the last segment exactly at the first segment's start.
  std::vector<ProfileSegment> close() {
    segments_.back().b = segments_.front().a;
    return segments_;
  }

 private:
  Vec2 position_ = Vec2::Zero();
  double heading_ = 0;
  std::vector<ProfileSegment> segments_;
};

/// The profile of the CAD-like part, counter-clockwise, in [0,2] × [0,0.7]. Crease angles
/// (between outward normals) at its corners are noted on each turn.
std::vector<ProfileSegment> fandisk_profile() {
  Turtle t;
  t.line(2.0);               // bottom
  t.turn(90);                // 90°
  t.line(0.4);               // right wall
  t.turn(45);                // 45°
  t.line(0.35);              // chamfer
  t.turn(30);                // 30°
  t.arc(1.5, 40);            // cylindrical roof …
  t.line(0.3);               // … blending tangentially into a flat slope (one smooth patch)
  t.turn(-115);              // 115°, concave
  t.line(0.25);              // step wall
  t.turn(90);                // 90°
  t.line(t.position().x());  // tower top
  t.turn(90);                // 90°
  t.line(t.position().y());  // left wall, back down to the start (90° with the bottom)
  return t.close();
}

/// Height of the slanted front cap above the back cap z = 0 (creases of 68°–112° with the walls).
double fandisk_front_z(const Vec2& p) { return 0.6 + 0.4 * p.x(); }

/// Surface patches of the part: bottom, right wall, chamfer, roof + slope, step wall, tower
/// top, left wall, back cap, front cap.
constexpr int kFandiskPatches = 9;
/// Target edge length times the resolution n.
constexpr double kFandiskEdge = 1.25;

}  // namespace

int fandisk_like_patch_count() { return kFandiskPatches; }

Mesh make_fandisk_like(int n) {
  require(n >= 1, int_message("make_fandisk_like", "n", ">= 1", n));
  const std::vector<ProfileSegment> profile = fandisk_profile();
  const int k = static_cast<int>(profile.size());
  const double h = kFandiskEdge / n;
  PatchMesher mesher([h](const Vec3&) { return h; }, InteriorSampling::Lattice);

  // Corners at the back (z = 0) and front of each profile vertex, then the curves joining them.
  std::vector<int> back(k), front(k);
  for (int j = 0; j < k; ++j) {
    const Vec2 p = profile[j].a;
    back[j] = mesher.add_corner(Vec3(p.x(), p.y(), 0));
    front[j] = mesher.add_corner(Vec3(p.x(), p.y(), fandisk_front_z(p)));
  }
  std::vector<std::vector<int>> along(k), back_curve(k), front_curve(k);
  for (int j = 0; j < k; ++j) {
    const Vec2 p = profile[j].a;
    const ProfileSegment& s = profile[j];
    along[j] =
        mesher.add_curve(back[j], front[j], [&](double t) { return Vec3(p.x(), p.y(), t * fandisk_front_z(p)); });
    back_curve[j] = mesher.add_curve(back[j], back[(j + 1) % k], [&](double t) {
      const Vec2 x = s.at(t);
      return Vec3(x.x(), x.y(), 0);
    });
    front_curve[j] = mesher.add_curve(front[j], front[(j + 1) % k], [&](double t) {
      const Vec2 x = s.at(t);
      return Vec3(x.x(), x.y(), fandisk_front_z(x));
    });
  }
  // Walls, developed isometrically into (arc length, z).
  for (int j = 0; j < k; ++j) {
    const ProfileSegment& s = profile[j];
    std::vector<int> loop;
    append_curve(loop, back_curve[j]);
    append_curve(loop, along[(j + 1) % k]);
    append_curve(loop, front_curve[j], true);
    append_curve(loop, along[j], true);
    const double length = s.length();
    mesher.add_patch(
        loop, [&](const Vec3& p) { return Vec2(s.arclength(p.head<2>()), p.z()); },
        [&](const Vec2& u) -> Vec3 {
          const Vec2 x = s.at(u.x() / length);
          return Vec3(x.x(), x.y(), u.y());
        });
  }
  // Back cap (outward -z: the profile reversed) and slanted front cap.
  std::vector<int> back_loop, front_loop;
  for (int j = k - 1; j >= 0; --j) append_curve(back_loop, back_curve[j], true);
  for (int j = 0; j < k; ++j) append_curve(front_loop, front_curve[j]);
  mesher.add_planar_patch(back_loop);
  mesher.add_planar_patch(front_loop);

  Mesh m = mesher.to_mesh();
  centre_bounding_box(m.V);
  return m;
}

}  // namespace msmesh
