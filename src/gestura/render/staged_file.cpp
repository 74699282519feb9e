#include "gestura/render/staged_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "gestura/core/error.hpp"

namespace gestura {

StagedFile::StagedFile(std::string target) : target_(std::move(target)) {
  if (target_.empty()) throw Error("no output file given");
  if (std::filesystem::is_directory(target_)) throw Error("cannot write " + target_ + ": it is a directory");
  std::string pattern = target_ + ".part-XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) throw Error("cannot write " + target_ + ": " + std::strerror(errno));
  // mkstemp creates the file private (0600); give it the mode a plain fopen would have.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  temp_ = name.data();
}

StagedFile::~StagedFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void StagedFile::commit() {
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temp_.c_str());
    committed_ = true;
    throw Error("cannot write " + target_ + ": " + reason);
  }
  committed_ = true;
}

}  // namespace gestura
