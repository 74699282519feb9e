#pragma once
// Running the gestura command line (or any shell command) from tests: exit status and the combined
// stdout + stderr.
#include <string>

namespace gestura::test {

struct CliRun {
  int status;          // exit status, or -1 when the command could not be started or was killed
  std::string output;  // stdout and stderr together
};

CliRun run_command(const std::string& command);
// `gestura ARGS` (the binary under test).
CliRun run_cli(const std::string& args);

}  // namespace gestura::test
