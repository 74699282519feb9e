#pragma once
// Every file gestura writes goes through here, so that no failure ever leaves a half-written file
// at the destination claiming success:
//   1. the data goes to a temporary file beside the target (same directory, same file system),
//   2. every write is checked (a full disk is an error, never a short file),
//   3. commit() flushes the temporary to the disk (fsync), renames it over the target (atomic on
//      POSIX) and syncs the directory, so the target is either the old file or the whole new one.
// An uncommitted StagedFile removes its temporary when destroyed; after
// remove_staged_files_on_signals(), SIGINT, SIGTERM and SIGHUP remove the live temporaries too
// before the process ends. Only `kill -9` (or a power cut) can leave a temporary behind, never a
// partial target: temporaries are named TARGET.part-XXXXXX. A target that is a symbolic link keeps
// being one (the file it points to is replaced); a device or pipe (/dev/null, /dev/stdout, a FIFO)
// is written straight, as there is nothing to stage.
//
// Writers that produce bytes in memory call write_file_atomically(); writers that hand a path to
// a library (ffmpeg) write into temp_path() and commit(); a writer of many files that belong
// together (OpenPose's one file per frame) uses StagedFileGroup.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gestura {

class StagedFile {
 public:
  // Creates the temporary file now, so an unwritable directory fails before any work is done.
  // Throws gestura::Error("cannot write TARGET: reason").
  explicit StagedFile(std::string target);
  ~StagedFile();  // removes the temporary unless committed
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::string& target() const { return target_; }
  const std::string& temp_path() const { return temp_; }

  // Appends `bytes` to the temporary. Throws gestura::Error("cannot write TARGET: reason") when the
  // disk is full or the output would pass kMaxOutputBytes (core/output_limits.hpp).
  void write(std::string_view bytes);
  // fsync, rename over the target, fsync the directory. Throws gestura::Error naming the target
  // when any step fails; the temporary is then removed and the target left as it was.
  void commit();

 private:
  void release();  // closes the descriptor and forgets the temporary for the signal handler

  std::string target_, destination_, temp_;  // destination: the target, or the file its link points to
  int fd_ = -1;
  int slot_ = -1;  // index in the signal handler's table of live temporaries, -1 when not there
  std::uint64_t written_ = 0;
  bool committed_ = false;
  bool direct_ = false;  // a device or pipe, written straight
};

// Writes `bytes` to `path` through a StagedFile: all or nothing.
void write_file_atomically(const std::string& path, std::string_view bytes);

// Files that appear together or not at all, all in one directory: each is written into a hidden
// staging directory beside them (DIRECTORY/.NAME.part-XXXXXX/), and commit() moves them into
// place with the termination signals held back. A failure, or destruction before commit(), leaves
// none of them at their destination.
class StagedFileGroup {
 public:
  // `directory` ("" = the current one) must exist; `label` names the group in the staging
  // directory's name and in errors.
  StagedFileGroup(std::string directory, std::string label);
  ~StagedFileGroup();
  StagedFileGroup(const StagedFileGroup&) = delete;
  StagedFileGroup& operator=(const StagedFileGroup&) = delete;

  // Writes DIRECTORY/NAME (name without a slash) into the staging directory; checked like
  // StagedFile::write.
  void write(const std::string& name, std::string_view bytes);
  // Moves every file into DIRECTORY; returns their paths in the order written.
  std::vector<std::string> commit();

 private:
  void remove_staging();

  std::string directory_, label_, staging_;
  std::vector<std::string> names_;
  int slot_ = -1;
  bool committed_ = false;
};

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the temporaries of every live
// StagedFile and StagedFileGroup, then end the process as the signal would have. Call once at
// start-up (the CLI does); later calls do nothing.
void remove_staged_files_on_signals();

}  // namespace gestura
