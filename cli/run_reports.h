// The reports of one run of `msmesh denoise`, `segment` and `inpaint` (their --report option),
// as HTML pages (report_page.h).
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/denoise.h"
#include "msmesh/inpaint.h"
#include "msmesh/mesh.h"
#include "msmesh/metrics.h"
#include "msmesh/report_page.h"
#include "msmesh/segment.h"

namespace msmesh::cli {

/// The report of `msmesh denoise`: input / result / truth meshes (error and edge field colour
/// modes), parameters, figures (MSAE, mean angle, flips, distances) and the residual plots.
/// `input_errors` and `result_errors` are evaluate() of input and result against *truth (read
/// only when truth is given).
void write_denoise_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const Eigen::MatrixXd& result_V, const Mesh* truth, const std::string& method,
                          const std::string& preset, const DenoiseOptions& options, const DenoiseResult& result,
                          const Evaluation& input_errors, const Evaluation& result_errors);

/// The report of `msmesh segment`: the mesh coloured by segment, its edge field, segment
/// table and the normal filtering plots.
void write_segment_report(const std::string& path, const std::string& input_path, const Mesh& mesh,
                          const SegmentOptions& options, const SegmentResult& result);

/// The report of `msmesh inpaint`: input and result (new faces tinted), truth when given,
/// the hole table and the plots of the last feature-recovery round.
void write_inpaint_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const InpaintResult& result, const Mesh* truth, const InpaintOptions& options);

}  // namespace msmesh::cli
