#pragma once
// Running the gestura command line (or any shell command) from tests: exit status and the combined
// stdout + stderr.
#include <string>

namespace gestura::test {

struct CliRun {
  int status;          // exit status, or -1 when the command could not be started or was killed
  std::string output;  // stdout and stderr together
};

// Runs `command` with sh. Its stderr goes to the captured stdout first, so redirections written in
// `command` still apply after that: `CMD >/dev/null` captures stderr alone.
CliRun run_command(const std::string& command);
// `gestura ARGS` (the binary under test); `env` is put before it as shell assignments, e.g.
// "GESTURA_LEXICON='/tmp/x.sqlite'".
CliRun run_cli(const std::string& args, const std::string& env = "");

}  // namespace gestura::test
