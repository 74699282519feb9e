#include "support/cli.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include "support/build_paths.hpp"

namespace gestura::test {

CliRun run_command(const std::string& command) {
  FILE* pipe = popen(("exec 2>&1\n" + command).c_str(), "r");
  if (!pipe) return {-1, ""};
  std::string out;
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

CliRun run_cli(const std::string& args, const std::string& env) {
  return run_command(env + " '" + gestura::test::cli_path() + "' " + args);
}

}  // namespace gestura::test
