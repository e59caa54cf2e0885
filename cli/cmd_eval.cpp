// msmesh eval: the literature's error figures of a result against a ground truth
// (DESIGN.md §"Measuring results").
#include <iostream>
#include <memory>

#include "command.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/metrics.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string result, truth;
  bool json = false, quiet = false;
};

void run(const Args& a) {
  Eigen::Index dropped_result = 0, dropped_truth = 0;
  const Mesh result = read_mesh(a.result, &dropped_result);
  const Mesh truth = read_mesh(a.truth, &dropped_truth);
  const Evaluation ev = evaluate(result.V, result.F, truth.V, truth.F);

  // Why normal metrics are missing, in the library's own words.
  std::string why;
  if (!ev.same_connectivity) {
    try {
      normal_errors(result.V, result.F, truth.V, truth.F);
    } catch (const InvalidInput& e) {
      why = e.what();
    }
    if (why.empty()) why = "normal metrics need equal connectivity";
  }

  const DistanceErrors& d = ev.distances;
  if (a.json) {
    Json j;
    j.add("result", a.result).add("truth", a.truth);
    j.add("result_faces", static_cast<long long>(result.F.rows()))
        .add("truth_faces", static_cast<long long>(truth.F.rows()));
    if (dropped_result) j.add("result_dropped_degenerate_faces", static_cast<long long>(dropped_result));
    if (dropped_truth) j.add("truth_dropped_degenerate_faces", static_cast<long long>(dropped_truth));
    j.add("same_connectivity", ev.same_connectivity);
    if (ev.same_connectivity) {
      j.add("msae", ev.normals.msae)
          .add("msae_e3", ev.normals.msae * 1e3)
          .add("mean_angle_deg", ev.normals.mean_angle_deg)
          .add("flipped", static_cast<long long>(ev.normals.flipped))
          .add("truth_folded", static_cast<long long>(ev.normals.truth_folded))
          .add("flipped_outside_folds", static_cast<long long>(ev.normals.flipped_outside_folds))
          .add("msae_outside_folds_e3", ev.normals.msae_outside_folds * 1e3);
    } else {
      j.add("normal_metrics", why);
    }
    j.add("dist_mean_e3", d.mean * 1e3)
        .add("dist_rms_e3", d.rms * 1e3)
        .add("dist_max_e3", d.max * 1e3)
        .add("dist_area_weighted_rms_e3", d.area_weighted_rms * 1e3);
    std::cout << j.str() << "\n";
    return;
  }

  if (a.quiet) return;
  std::cout << "eval: " << a.result << " (" << result.F.rows() << " faces) against " << a.truth << " ("
            << truth.F.rows() << " faces)\n";
  if (dropped_result || dropped_truth)
    std::cout << "  note: faces repeating a vertex were dropped on reading: " << dropped_result << " in the result, "
              << dropped_truth << " in the truth\n";
  if (ev.same_connectivity) {
    std::cout << "  MSAE (the paper's mean squared angular error, mean of theta^2 in rad^2): "
              << fmt(ev.normals.msae * 1e3) << " x 1e-3\n";
    std::cout << "  mean normal angle:      " << fmt(ev.normals.mean_angle_deg) << " deg\n";
    std::cout << "  flipped faces (> 90 deg): " << ev.normals.flipped << " of " << result.F.rows() << "\n";
    if (ev.normals.truth_folded > 0)
      std::cout << "  the truth folds " << ev.normals.truth_folded
                << " faces against their neighbours; without them: MSAE " << fmt(ev.normals.msae_outside_folds * 1e3)
                << " x 1e-3, flipped " << ev.normals.flipped_outside_folds << "\n";
  } else {
    std::cout << "  " << why << "; only distances are reported\n";
  }
  std::cout << "  vertex-to-truth-surface distance (x 1e-3 of the truth's bounding-box diagonal):\n";
  std::cout << "    mean " << fmt(d.mean * 1e3) << ", RMS " << fmt(d.rms * 1e3) << ", max " << fmt(d.max * 1e3) << "\n";
  std::cout << "    area-weighted RMS (Sun et al. 2007 E_v): " << fmt(d.area_weighted_rms * 1e3) << "\n";
}

const Registrar kRegistration("eval", 40, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("eval", "Error figures of a result against a ground-truth mesh");
  c->add_option("result", a->result, "Result mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("--truth", a->truth, "Ground-truth mesh")->required();
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
