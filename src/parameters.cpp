#include "msmesh/parameters.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <sstream>

#include "msmesh/bilateral.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/inpaint.h"
#include "msmesh/normal_filter.h"
#include "msmesh/segment.h"
#include "msmesh/vertex_update.h"

namespace msmesh {

// ---- ranges and values ----------------------------------------------------------------

bool ParameterRange::contains(double x) const {
  if (std::isnan(x)) return false;
  if (min_open ? !(x > min) : !(x >= min)) return false;
  if (max_open ? !(x < max) : !(x <= max)) return false;
  return true;
}

namespace {

std::string shortest(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (std::isnan(x)) return "nan";
  char buf[64];
  if (x == std::floor(x) && std::abs(x) < 1e15) {  // whole numbers in full: 100000, not 1e+05
    const auto r = std::to_chars(buf, buf + sizeof buf, static_cast<long long>(x));
    return std::string(buf, r.ptr);
  }
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string ParameterRange::describe() const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max)
    return std::string("in ") + (min_open ? "(" : "[") + shortest(min) + ", " + shortest(max) + (max_open ? ")" : "]");
  if (has_min) return (min_open ? "> " : ">= ") + shortest(min);
  if (has_max) return (max_open ? "< " : "<= ") + shortest(max);
  return "any finite number";
}

std::string ParameterInfo::key() const {
  std::string k = name;
  std::replace(k.begin(), k.end(), '-', '_');
  return k;
}

std::string ParameterInfo::describe_range() const {
  switch (type) {
    case ParameterType::Boolean:
      return "0 or 1";
    case ParameterType::Integer:
      return "a whole number " + range.describe();
    case ParameterType::Real:
      break;
  }
  return range.describe();
}

std::string ParameterInfo::format(double value) const {
  if (type == ParameterType::Boolean) return value != 0 ? "on" : "off";
  return shortest(value);
}

void check_parameter(const ParameterInfo& p, double value, const std::string& as_typed) {
  bool ok = std::isfinite(value) && p.range.contains(value);
  if (p.type == ParameterType::Integer) ok = ok && value == std::floor(value);
  if (p.type == ParameterType::Boolean) ok = value == 0 || value == 1;
  if (ok) return;
  std::ostringstream os;
  os << p.group << ": " << (as_typed.empty() ? p.name : as_typed) << " = " << shortest(value)
     << " is out of range; valid: " << p.describe_range();
  throw InvalidInput(os.str());
}

void check_parameter(const std::string& group, const std::string& name, double value, const ParameterRange& range) {
  ParameterInfo p;
  p.name = name;
  p.group = group;
  p.range = range;
  check_parameter(p, value);
}

double parse_parameter(const ParameterInfo& p, const std::string& text, const std::string& as_typed) {
  const std::string who = as_typed.empty() ? p.name : as_typed;
  if (p.type == ParameterType::Boolean) {
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* yes : {"1", "true", "yes", "on"})
      if (t == yes) return 1.0;
    for (const char* no : {"0", "false", "no", "off"})
      if (t == no) return 0.0;
    throw InvalidInput(p.group + ": " + who + " = '" + text + "' is not a boolean; valid: 0 or 1 (true/false)");
  }
  double x = 0;
  const char* b = text.data();
  const char* e = b + text.size();
  const auto r = std::from_chars(b, e, x);
  if (text.empty() || r.ec != std::errc() || r.ptr != e)
    throw InvalidInput(p.group + ": " + who + " = '" + text + "' is not a number; valid: " + p.describe_range());
  check_parameter(p, x, as_typed);
  return x;
}

// ---- the tables -------------------------------------------------------------------------

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Fill densities above this make CGAL's refinement produce about density² times more faces
// than the mesh around the hole has: 1000 grew past 1.7 GB for two small holes.
constexpr double kMaxFillDensity = 20;
constexpr double kGoldenRatio = 1.6180339887498949;  // (1 + √5)/2, the multiplier step's bound (§5.1)

ParameterRange positive() { return {0, kInf, true, false}; }
ParameterRange non_negative() { return {0, kInf, false, false}; }
ParameterRange closed(double lo, double hi) { return {lo, hi, false, false}; }
ParameterRange open(double lo, double hi) { return {lo, hi, true, true}; }
ParameterRange left_open(double lo, double hi) { return {lo, hi, true, false}; }
ParameterRange right_open(double lo, double hi) { return {lo, hi, false, true}; }

ParameterInfo real(const char* name, const char* symbol, const char* unit, ParameterRange range, const char* help,
                   const char* group) {
  return {name, symbol, unit, ParameterType::Real, range, help, group};
}
ParameterInfo integer(const char* name, const char* symbol, ParameterRange range, const char* help, const char* group) {
  return {name, symbol, "", ParameterType::Integer, range, help, group};
}
ParameterInfo boolean(const char* name, const char* help, const char* group) {
  return {name, "", "", ParameterType::Boolean, closed(0, 1), help, group};
}

/// Binds a parameter to one field (double, int or bool) of Options.
template <class Options, class T>
Parameter<Options> field(ParameterInfo info, T Options::*m) {
  return bind_parameter(std::move(info), m);
}

/// The entries of `inner` applied to the member `m` of Outer, except those named in `skip`.
template <class Outer, class Inner>
void append(ParameterTable<Outer>& out, const ParameterTable<Inner>& inner, Inner Outer::*m,
            std::initializer_list<const char*> skip = {}) {
  for (const Parameter<Inner>& p : inner) {
    if (std::any_of(skip.begin(), skip.end(), [&](const char* s) { return p.info.name == s; })) continue;
    out.push_back({p.info, [get = p.get, m](const Outer& o) { return get(o.*m); },
                   [set = p.set, m](Outer& o, double x) { set(o.*m, x); }});
  }
}

const char* const kNormals = "normal filtering";
const char* const kVertices = "vertex update";
const char* const kBilateral = "bilateral filtering";
const char* const kSolver = "solver";
const char* const kInpaint = "inpainting";
const char* const kSegment = "segmentation";

ParameterInfo solver_tolerance_info() {
  return real("solver-tolerance", "", "", open(0, 1),
              "relative residual at which conjugate gradients stop (at 1e-6 or above, the normal filter's early "
              "N-steps stop sooner: at a hundredth of the normals' last relative change, up to 1e-4)",
              kSolver);
}

/// One solver-tolerance for the normal filter's and the vertex update's solvers of Options
/// (DenoiseOptions, InpaintOptions).
template <class Options>
Parameter<Options> shared_solver_tolerance() {
  return {solver_tolerance_info(), [](const Options& o) { return o.normals.solver_tolerance; },
          [](Options& o, double x) { o.normals.solver_tolerance = o.vertices.solver_tolerance = x; }};
}

}  // namespace

const ParameterTable<NormalFilterOptions>& normal_filter_parameters() {
  using O = NormalFilterOptions;
  static const ParameterTable<O> t = {
      field(real("alpha", "α", "", positive(), "fidelity to the input normals (eq. 15)", kNormals), &O::alpha),
      field(real("beta", "β", "", positive(), "weight of the edge-set (Ambrosio-Tortorelli) term", kNormals), &O::beta),
      field(real("gamma", "γ", "", positive(), "weight of the normal-variation term", kNormals), &O::gamma),
      field(real("epsilon", "ε", "mean edge lengths", positive(), "phase-field width of the edge field v", kNormals),
            &O::epsilon),
      field(real("rho", "ρ", "", positive(), "non-convexity of the log penalty log(1 + ρt)/ρ", kNormals), &O::rho),
      field(real("penalty", "r", "", positive(), "ADMM penalty", kNormals), &O::penalty),
      field(real("nu", "ν", "", open(0, kGoldenRatio), "ADMM multiplier step", kNormals), &O::relaxation),
      field(real("v0", "v⁰", "", closed(0, 1), "initial edge field", kNormals), &O::v_initial),
      field(integer("normal-iterations", "", closed(1, 100000), "maximum normal filtering iterations", kNormals),
            &O::max_iterations),
      field(real("normal-tolerance", "ε₁", "", non_negative(),
                 "stop normal filtering when ‖N^{k+1} − N^k‖_U is below this", kNormals),
            &O::tolerance),
      field(boolean("project-each-iteration",
                    "project the normals onto the unit sphere after every N-step (the paper's reading; off: once at "
                    "the end)",
                    kNormals),
            &O::project_each_iteration),
      field(real("polish", "λ", "", non_negative(),
                 "weight of the final bilateral polish of the filtered normals, guided by them and masked by v (0: "
                 "none, as the paper)",
                 kNormals),
            &O::polish),
      field(real("polish-range", "σ_p", "", positive(),
                 "range width of the polish: normals further apart than about twice this are not averaged", kNormals),
            &O::polish_range),
      field(solver_tolerance_info(), &O::solver_tolerance),
  };
  return t;
}

const ParameterTable<VertexUpdateOptions>& vertex_update_parameters() {
  using O = VertexUpdateOptions;
  static const ParameterTable<O> t = {
      field(real("omega1", "ω₁", "", positive(), "weight of matching the filtered normals (eq. 24)", kVertices),
            &O::omega1),
      field(real("omega2", "ω₂", "", non_negative(), "fairness across edges, weighted by v²", kVertices), &O::omega2),
      field(real("omega3", "ω₃", "", positive(), "closeness to the input positions", kVertices), &O::omega3),
      field(real("fairness-tangential", "τ", "", closed(0, 1),
                 "share of the fairness term acting along the surface (1: the paper's; 0: along the normals only)",
                 kVertices),
            &O::fairness_tangential),
      field(integer("vertex-iterations", "", closed(1, 100000), "maximum vertex update iterations", kVertices),
            &O::max_iterations),
      field(real("vertex-tolerance", "ε₂", "mean edge lengths", non_negative(),
                 "stop the vertex update when the RMS vertex move is below this", kVertices),
            &O::tolerance),
      field(integer("vertex-acceleration", "", closed(0, 20),
                    "Anderson acceleration depth of the vertex update (0: the paper's plain alternation)", kVertices),
            &O::acceleration),
      field(solver_tolerance_info(), &O::solver_tolerance),
  };
  return t;
}

const ParameterTable<BilateralOptions>& bilateral_parameters() {
  using O = BilateralOptions;
  static const ParameterTable<O> t = {
      field(integer("bilateral-iterations", "", closed(1, 10000), "bilateral normal filtering passes", kBilateral),
            &O::normal_iterations),
      field(real("sigma-r", "σ_r", "", left_open(0, 2), "range (normal difference) Gaussian width", kBilateral),
            &O::sigma_r),
      field(real("sigma-s", "σ_s", "mean edge lengths", non_negative(),
                 "spatial Gaussian width; 0: the mean distance between adjacent face centres", kBilateral),
            &O::sigma_s),
      field(integer("vertex-iterations", "", closed(1, 100000), "vertex update passes", kBilateral),
            &O::vertex_iterations),
  };
  return t;
}

const ParameterTable<DenoiseOptions>& denoise_parameters() {
  using O = DenoiseOptions;
  static const ParameterTable<O> t = [] {
    ParameterTable<O> t;
    append(t, normal_filter_parameters(), &O::normals, {"solver-tolerance"});
    append(t, vertex_update_parameters(), &O::vertices, {"vertex-iterations", "solver-tolerance"});
    // One vertex-iterations for both vertex updates (NMSTV/MSTV's and the bilateral one).
    t.push_back(
        {find_parameter(vertex_update_parameters(), "vertex-iterations")->info,
         [](const O& o) { return static_cast<double>(o.vertices.max_iterations); },
         [](O& o, double x) { o.vertices.max_iterations = o.bilateral.vertex_iterations = static_cast<int>(x); }});
    append(t, bilateral_parameters(), &O::bilateral, {"vertex-iterations"});
    t.push_back(field(integer("prefilter", "", closed(0, 1000),
                              "Taubin passes on a copy of the vertices before the first normals N⁰ are taken "
                              "(robust first normals under heavy noise; 0: the input's face normals, as the paper)",
                              kNormals),
                      &O::prefilter_iterations));
    t.push_back(field(real("despike", "", "robust σ", non_negative(),
                           "move vertices farther than this many robust σ from a low-pass copy onto it before "
                           "anything else (impulsive outliers; 0: off, as the paper)",
                           kNormals),
                      &O::despike_threshold));
    t.push_back(field(integer("planes", "", closed(0, 2147483647),
                              "smallest flat region, in faces, whose filtered normals are replaced by its fitted "
                              "plane's (neighbours within 1°, all within 4° of their mean; 0: off, as the paper)",
                              kNormals),
                      &O::plane_min_faces));
    t.push_back(field(integer("jet-rings", "", closed(0, 10),
                              "rings of the quadrics fitted to the updated vertices whose normals become the "
                              "targets of faces on curved parts (not across creases, not inside flat plateaus) "
                              "for a second vertex update (0: off, as the paper)",
                              kNormals),
                      &O::jet_rings));
    t.push_back(field(real("unreachable-angle", "", "degrees", closed(0, 180),
                           "a face whose normal after the vertex update lies farther than this from its target "
                           "loses that target and follows its neighbours in a second vertex update (a face given "
                           "the other side of a crease; 0: off, as the paper)",
                           kNormals),
                      &O::unreachable_angle));
    t.push_back(field(integer("min-component-faces", "", closed(0, 2147483647),
                              "components (vertex-connected) of fewer faces are kept as they are: too few to tell "
                              "noise from shape (0: every component denoised, as the paper)",
                              kNormals),
                      &O::min_component_faces));
    t.push_back(shared_solver_tolerance<O>());
    return t;
  }();
  return t;
}

const ParameterTable<InpaintOptions>& inpaint_parameters() {
  using O = InpaintOptions;
  static const ParameterTable<O> t = [] {
    ParameterTable<O> t = {
        field(integer("max-hole-edges", "", closed(0, 2147483647), "skip holes with more boundary edges (0: no limit)",
                      kInpaint),
              &O::max_hole_edges),
        field(real("max-hole-diameter", "", "mean edge lengths", non_negative(),
                   "skip holes wider than this (0: no limit)", kInpaint),
              &O::max_hole_diameter),
        field(boolean("fill-outer", "also fill the outer boundary of an open surface", kInpaint),
              &O::fill_outer_boundary),
        field(real("density", "", "", closed(0, kMaxFillDensity),
                   "CGAL density_control_factor of the fill (0: √2 without feature recovery, feature-density with it)",
                   kInpaint),
              &O::density),
        field(real("feature-density", "", "", left_open(0, kMaxFillDensity),
                   "density of the fill where features are recovered", kInpaint),
              &O::feature_density),
        field(boolean("features", "recover the sharp features running into the holes (off: CGAL's fill-and-fair only)",
                      kInpaint),
              &O::recover_features),
        field(real("feature-angle", "", "degrees", open(0, 180),
                   "input edges sharper than this at a hole's boundary are creases", kInpaint),
              &O::feature_angle),
        field(real("smooth-angle", "", "degrees", left_open(0, 180),
                   "median dihedral angle below which the other boundary edges count as smooth", kInpaint),
              &O::smooth_angle),
        field(boolean("all-holes-features", "recover features in every filled hole, creases or not", kInpaint),
              &O::all_holes_featured),
        field(integer("free-ring", "", closed(0, 1000),
                      "rings of input vertices around each hole that may move (0: input vertices stay exactly)",
                      kInpaint),
              &O::free_ring),
        field(real("outside-alpha", "", "", positive(), "α multiplier on input faces", kInpaint), &O::outside_alpha),
        field(real("inside-alpha", "", "", non_negative(), "α multiplier on new faces", kInpaint), &O::inside_alpha),
        field(real("inside-beta", "", "", positive(), "β multiplier on edges of new faces (paper: 0.1)", kInpaint),
              &O::inside_beta),
        field(real("inside-omega3", "", "", non_negative(), "ω₃ multiplier on new vertices", kInpaint),
              &O::inside_omega3),
        field(real("ring-omega3", "", "", positive(), "ω₃ multiplier on input vertices freed by free-ring", kInpaint),
              &O::ring_omega3),
        field(real("pinned-omega3", "", "", positive(), "ω₃ multiplier that pins the other input vertices", kInpaint),
              &O::pinned_omega3),
        field(integer("context-rings", "", closed(1, 1000), "rings of input faces around each hole in the solves",
                      kInpaint),
              &O::context_rings),
        field(boolean("smoothing", "piecewise-smooth completion of the new faces' normals", kInpaint),
              &O::smooth_normals),
        field(real("jump-angle", "", "degrees", right_open(0, 180),
                   "normals further apart than this form the edge set (0: per hole from its creases)", kInpaint),
              &O::smooth_jump_angle),
        field(boolean("placement", "place the new vertices by the convex orthogonal solve first", kInpaint),
              &O::orthogonal_placement),
        field(real("placement-smoothing", "", "", positive(), "membrane weight of the orthogonal placement", kInpaint),
              &O::placement_smoothing),
        field(boolean("crease-flips", "flip edges of new faces towards the creases", kInpaint), &O::crease_flips),
        field(integer("rounds", "", closed(1, 100), "rounds of normal filtering + vertex update", kInpaint),
              &O::rounds),
    };
    append(t, normal_filter_parameters(), &O::normals, {"solver-tolerance"});
    append(t, vertex_update_parameters(), &O::vertices, {"solver-tolerance"});
    t.push_back(shared_solver_tolerance<O>());
    return t;
  }();
  return t;
}

const ParameterTable<SegmentOptions>& segment_parameters() {
  using O = SegmentOptions;
  static const ParameterTable<O> t = [] {
    ParameterTable<O> t = {
        field(real("angle", "", "degrees", open(0, 180),
                   "faces whose regularised normals are within this angle never split", kSegment),
              &O::smooth_angle_deg),
        field(real("clamp", "", "", open(0, 0.5), "split probabilities are clamped to [clamp, 1 − clamp]", kSegment),
              &O::clamp_probability),
        field(real("min-area", "", "", right_open(0, 1),
                   "merge segments below this fraction of the total area into a neighbour (0: off)", kSegment),
              &O::min_area_fraction),
    };
    append(t, normal_filter_parameters(), &O::normals);
    return t;
  }();
  return t;
}

}  // namespace msmesh
