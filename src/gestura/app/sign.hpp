#pragma once
// sign: one sign written in HamNoSys or SiGML, performed on an avatar and written out.
#include <optional>
#include <string>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"
#include "gestura/app/notice.hpp"
#include "gestura/app/sign_source.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace gestura::app {

struct SignRequest {
  SignSource source;
  float speed = 1.0f;
  AvatarChoice avatar;
  MotionOutput output;  // required

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    SignSource::fields(self.source, visit);
    visit(self.speed, FieldInfo{.name = "speed", .help = "tempo factor", .value = "S", .min = 0.25, .max = 4});
    AvatarChoice::fields(self.avatar, visit);
    MotionOutput::fields(self.output, visit);
  }
};

struct SignResult {
  SignSynthesis synthesis;             // clip, plan (sign_start, sign_end), stats, non-manual warnings
  std::optional<std::string> problem;  // why the performance falls short of the notation (check's rules)
  std::vector<Notice> notices;         // the non-manual warnings and the problem, for display
  WrittenFile written;
};

void validate(const SignRequest& request);
SignResult run(const SignRequest& request, const RunContext& context = {});
// The performance alone, nothing written (the output fields are ignored): for adapters that send
// the clip on themselves (the server).
SignResult perform(const SignRequest& request, const RunContext& context = {});

nlohmann::json to_json(const SignResult& result);

}  // namespace gestura::app
