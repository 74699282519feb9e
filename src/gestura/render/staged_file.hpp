#pragma once
// Writing a file so that a failure never leaves a half-written file claiming success: the data
// goes to a temporary file beside the target (same directory, so the final rename is atomic) and
// commit() renames it over the target. Destroying an uncommitted StagedFile removes the temporary.
#include <string>

namespace gestura {

class StagedFile {
 public:
  // Creates the temporary file now, so an unwritable directory fails before any work is done.
  // Throws gestura::Error("cannot write TARGET: reason").
  explicit StagedFile(std::string target);
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::string& target() const { return target_; }
  const std::string& temp_path() const { return temp_; }
  void commit();  // throws gestura::Error when the rename fails (the temporary is removed)

 private:
  std::string target_, temp_;
  bool committed_ = false;
};

}  // namespace gestura
