// Preset auto's second round under heavy noise (msmesh/second_round.h): its weight from the
// first estimate, what the two rounds compute, and that the caller's settings reach both.
#include <gtest/gtest.h>

#include <string>

#include "msmesh/denoise.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/presets.h"
#include "msmesh/second_round.h"
#include "msmesh/shapes.h"

using namespace msmesh;

namespace {

Eigen::MatrixXd noisy(const Mesh& m, double sigma) {
  NoiseOptions no;
  no.sigma = sigma;
  no.seed = 11;
  return add_noise(m.V, m.F, no);
}

}  // namespace

TEST(SecondRound, ItsWeightRisesWithTheNoiseFromThreeTenthsToFourTenths) {
  const Mesh m = make_shape("cube", 16);
  const ResolvedPreset heavy = resolve_preset("auto", noisy(m, 0.7), m.F);
  ASSERT_GE(heavy.noise.sigma_rms, 0.4) << heavy.reason();
  EXPECT_EQ(heavy.second_round, 1.0) << heavy.reason();
  EXPECT_NE(heavy.reason().find("second round 1.00"), std::string::npos) << heavy.reason();
  const ResolvedPreset light = resolve_preset("auto", noisy(m, 0.2), m.F);
  ASSERT_LT(light.noise.sigma_rms, 0.3) << light.reason();
  EXPECT_EQ(light.second_round, 0.0) << light.reason();
  EXPECT_EQ(light.reason().find("second round"), std::string::npos) << light.reason();
  // Between the ends the weight is linear in strength × σ_rms: the strength moves it.
  const Eigen::MatrixXd V = noisy(m, 0.7);
  const ResolvedPreset weaker =
      resolve_preset("auto", V, m.F, 0.3 / heavy.noise.sigma_rms + 0.5 * 0.1 / heavy.noise.sigma_rms);
  EXPECT_NEAR(weaker.second_round, 0.5, 1e-9) << weaker.reason();
  // A named preset has none.
  EXPECT_EQ(resolve_preset("cad", V, m.F).second_round, 0.0);
}

TEST(SecondRound, IsAutoAgainOnTheResultBlendedInByItsWeight) {
  const Mesh m = make_shape("cube", 16);
  const Eigen::MatrixXd V = noisy(m, 0.7);
  ResolvedPreset first = resolve_preset("auto", V, m.F);
  ASSERT_EQ(first.second_round, 1.0) << first.reason();
  int adjusted = 0;
  const AdjustOptions count = [&](DenoiseOptions&) { ++adjusted; };
  SecondRound second;
  const DenoiseResult two = denoise_in_rounds(V, m.F, first, first.options, count, {}, &second);
  EXPECT_EQ(adjusted, 1);  // the second round's options (the caller adjusted the first's)
  EXPECT_EQ(second.weight, 1.0);
  // By hand: one round, auto on its result, a second denoise.
  const DenoiseResult one = denoise(V, m.F, first.options);
  const ResolvedPreset again = resolve_preset("auto", one.V, m.F);
  EXPECT_EQ(second.preset.reason(), again.reason());
  const DenoiseResult by_hand = denoise(one.V, m.F, again.options);
  EXPECT_LT((two.V - by_hand.V).cwiseAbs().maxCoeff(), 1e-12);
  // Better than the first round alone on this heavy noise (MSAE 11.6 → 6.7 ×10⁻³ at r 24).
  const double e1 = normal_errors(one.V, m.F, m.V, m.F).msae, e2 = normal_errors(two.V, m.F, m.V, m.F).msae;
  EXPECT_LT(e2, 0.9 * e1) << e1 << " -> " << e2;
  // Half the weight: halfway between the two rounds' positions.
  first.second_round = 0.5;
  const DenoiseResult half = denoise_in_rounds(V, m.F, first, first.options, {});
  EXPECT_LT((half.V - 0.5 * (one.V + by_hand.V)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SecondRound, NoneUnderLightNoiseOrForANamedPreset) {
  const Mesh m = make_shape("cube", 16);
  const Eigen::MatrixXd V = noisy(m, 0.2);
  const ResolvedPreset light = resolve_preset("auto", V, m.F);
  int adjusted = 0;
  const AdjustOptions count = [&](DenoiseOptions&) { ++adjusted; };
  SecondRound second;
  const DenoiseResult r = denoise_in_rounds(V, m.F, light, light.options, count, {}, &second);
  EXPECT_EQ(adjusted, 0);
  EXPECT_EQ(second.weight, 0.0);
  EXPECT_EQ(r.V, denoise(V, m.F, light.options).V);
  // A named preset under heavy noise: one round.
  const Eigen::MatrixXd heavy = noisy(m, 0.7);
  const ResolvedPreset cad = resolve_preset("cad", heavy, m.F);
  EXPECT_EQ(denoise_in_rounds(heavy, m.F, cad, cad.options, count).V, denoise(heavy, m.F, cad.options).V);
  EXPECT_EQ(adjusted, 0);
}
