#include "support/small_tmpfs.hpp"

#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace gestura::test {

SmallTmpfs::SmallTmpfs(std::size_t bytes) {
  if (geteuid() != 0) {
    skip_reason_ = "mounting a small tmpfs needs root (CI runs as root); not root here";
    return;
  }
  std::string pattern = (std::filesystem::temp_directory_path() / "gestura-tmpfs-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    skip_reason_ = std::string("cannot make a mount point: ") + std::strerror(errno);
    return;
  }
  root_ = pattern;
  const std::string options = "size=" + std::to_string(bytes) + ",mode=0777";
  if (mount("tmpfs", root_.c_str(), "tmpfs", 0, options.c_str()) != 0) {
    skip_reason_ = std::string("cannot mount a tmpfs (") + std::strerror(errno) + "), e.g. in a container without CAP_SYS_ADMIN";
    rmdir(root_.c_str());
    return;
  }
  mounted_ = true;
}

SmallTmpfs::~SmallTmpfs() {
  if (!mounted_) return;
  umount2(root_.c_str(), MNT_DETACH);
  rmdir(root_.c_str());
}

void SmallTmpfs::fill(std::size_t leave_bytes) {
  const std::string filler = path("filler");
  const int fd = open(filler.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) throw std::runtime_error("cannot create " + filler);
  const std::string page(4096, 'f');
  while (write(fd, page.data(), page.size()) > 0) {
  }
  // Full now; give back whole pages until `leave_bytes` are free.
  const off_t size = lseek(fd, 0, SEEK_END);
  const off_t keep = std::max<off_t>(0, size - static_cast<off_t>((leave_bytes + 4095) / 4096 * 4096));
  if (ftruncate(fd, keep) != 0) throw std::runtime_error("cannot shrink " + filler);
  close(fd);
}

void SmallTmpfs::empty_filler() { std::filesystem::remove(path("filler")); }

void SmallTmpfs::remount_read_only() {
  if (mount("tmpfs", root_.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, nullptr) != 0)
    throw std::runtime_error(std::string("cannot remount read-only: ") + std::strerror(errno));
}

std::vector<std::string> SmallTmpfs::entries() const {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(root_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace gestura::test
