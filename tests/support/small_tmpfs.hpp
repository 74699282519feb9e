#pragma once
// A tmpfs of a few hundred kilobytes mounted for one test, to see how writers meet a full disk and
// how readers meet a read-only file system. Mounting needs root (CI runs as root); elsewhere the
// tests that use it skip with the reason.
#include <cstddef>
#include <string>
#include <vector>

namespace gestura::test {

class SmallTmpfs {
 public:
  explicit SmallTmpfs(std::size_t bytes = 256 * 1024);
  ~SmallTmpfs();  // unmounts and removes the mount point
  SmallTmpfs(const SmallTmpfs&) = delete;
  SmallTmpfs& operator=(const SmallTmpfs&) = delete;

  bool mounted() const { return mounted_; }
  const std::string& skip_reason() const { return skip_reason_; }
  const std::string& root() const { return root_; }
  std::string path(const std::string& name) const { return root_ + "/" + name; }

  // Fills the file system with the file "filler" until about `leave_bytes` (whole pages) are free.
  void fill(std::size_t leave_bytes);
  // Frees what fill() took.
  void empty_filler();
  void remount_read_only();
  // Names in the root directory (hidden ones too), sorted.
  std::vector<std::string> entries() const;

 private:
  std::string root_, skip_reason_;
  bool mounted_ = false;
};

}  // namespace gestura::test
