#include "gestura/app/check.hpp"

#include <optional>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace gestura::app {

void validate(const CheckRequest& request) {
  check_fields(request);
  const std::string ext = lower_extension(request.file);
  if (!request.file.empty() && ext != ".jsonl" && ext != ".sigml")
    usage_error("file", request.file + ": unknown file type: expected .jsonl or .sigml");
}

CheckResult run(const CheckRequest& request, const RunContext& context) {
  validate(request);
  require_file("file", request.file);
  const std::string text = sign::read_text_file(request.file);
  // Text files have no NUL bytes; anything else (an image, an archive) is refused as a whole.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw AppError(ErrorCategory::input, Place{"file", {request.file}},
                   "not a text file (a NUL byte at offset " + std::to_string(nul) + ")");
  sign::CheckOptions options;
  options.parse.strict = request.strict;
  options.describe_parsed = request.show;
  options.max_failures = request.max_errors;
  CheckResult result;
  result.synthesized = !request.parse_only;
  // Synthesis on the default avatar's rig, built once for the whole file (or the workspace's).
  std::optional<RunWorkspace> workspace;
  if (result.synthesized) {
    workspace.emplace(context);
    options.synthesize = synthesis_check((*workspace)->rig(AvatarChoice{}));
  }
  result.report = has_extension(request.file, ".jsonl") ? sign::check_jsonl(text, request.file, options)
                                                        : sign::check_sigml(text, request.file, options);
  return result;
}

nlohmann::json to_json(const CheckResult& result) {
  const sign::CheckReport& r = result.report;
  return {{"signs", r.signs},       {"parsed", r.parsed},     {"synthesized", r.synthesized},
          {"failed", r.failed},     {"failures", r.failures}, {"notes", r.notes}, {"clips", r.clips},
          {"stopped", r.stopped},   {"descriptions", r.descriptions}};
}

}  // namespace gestura::app
