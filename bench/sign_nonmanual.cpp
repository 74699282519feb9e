// The cost of a SiGML sign's non-manual tiers on top of its manual synthesis: planning the tiers and
// writing face channels, head keys, joint offsets and the hand-following gaze into the clip.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "gestura/sign/sigml.hpp"
#include "gestura/sign/sign_synthesis.hpp"

using namespace gestura;

namespace {

// A sign at the chest with one value on most tiers (the eyes follow the hand every frame).
constexpr const char* kSign = R"(<sigml><hns_sign gloss="b"><hamnosys_nonmanual>
<hnm_head tag="SH"/><hnm_shoulder tag="UB"/><hnm_body tag="TF"/><hnm_eyegaze tag="HI"/>
<hnm_eyebrows tag="RB"/><hnm_eyelids tag="WB"/><hnm_mouthgesture tag="C01"/><hnm_mouthpicture picture="haUs"/>
</hamnosys_nonmanual><hamnosys_manual><hamflathand/><hamextfingeru/><hampalml/><hamchest/><hammoveo/>
</hamnosys_manual></hns_sign></sigml>)";

void S2_NonManualTiersOfOneSign(benchmark::State& state) {
  static const Avatar avatar = build_avatar();
  static const SigningRig rig = make_signing_rig(avatar);
  const sign::SigmlSign sign = sign::read_sigml(kSign).at(0);
  const SignSynthesis manual = synthesize_sign(sign.manual, rig);
  for (auto _ : state) {
    Clip clip = manual.clip;
    const auto warnings = add_sign_nonmanuals(sign.nonmanual, manual.plan.sign_start, manual.plan.sign_end, rig, 30.0f, clip);
    benchmark::DoNotOptimize(warnings.size());
    benchmark::DoNotOptimize(clip.duration);
  }
  state.counters["values"] = static_cast<double>(sign.nonmanual.size());
}
BENCHMARK(S2_NonManualTiersOfOneSign)->Unit(benchmark::kMicrosecond);

}  // namespace
