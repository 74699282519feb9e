#include "gestura/core/staged_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"

namespace gestura {

namespace {

// ---- the live temporaries, as the signal handler sees them ------------------------------------
// A fixed table of paths, so the handler touches no allocator and takes no lock: a slot is claimed
// with a compare-and-swap, filled, then published by its state. A path too long for a slot, or a
// full table, only means that temporary is not removed on a signal (its owner still removes it).

constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kFile = 2, kDirectory = 3 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes];
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free atomic");

Slot g_slots[kSlots];

int register_temporary(const std::string& path, SlotState kind) {
  if (path.size() >= kPathBytes) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(kind, std::memory_order_release);
    return i;
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_slots[slot].state.store(kFree, std::memory_order_release);
}

// Async-signal-safe: removes the plain files of a staging directory, then the directory.
void remove_directory(const char* path) {
  const int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    alignas(8) char buffer[4096];
    for (;;) {
      const long n = syscall(SYS_getdents64, fd, buffer, sizeof buffer);
      if (n <= 0) break;
      for (long at = 0; at < n;) {
        // struct linux_dirent64: u64 inode, s64 offset, u16 record length, u8 type, name.
        unsigned short length = 0;
        std::memcpy(&length, buffer + at + 16, sizeof length);
        const char* name = buffer + at + 19;
        if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) unlinkat(fd, name, 0);
        at += length;
      }
    }
    close(fd);
  }
  rmdir(path);
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  const int saved = errno;
  for (Slot& slot : g_slots) {
    const int state = slot.state.load(std::memory_order_acquire);
    if (state == kFile) unlink(slot.path);
    else if (state == kDirectory) remove_directory(slot.path);
  }
  errno = saved;
  // SA_RESETHAND put the default action back; the signal is delivered again as the handler returns.
  raise(signal_number);
}

constexpr int kTerminationSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Holds the termination signals back while a group of files moves into place.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t held;
    sigemptyset(&held);
    for (int s : kTerminationSignals) sigaddset(&held, s);
    pthread_sigmask(SIG_BLOCK, &held, &before_);
  }
  ~SignalsHeld() { pthread_sigmask(SIG_SETMASK, &before_, nullptr); }

 private:
  sigset_t before_;
};

// ---- checked system calls ---------------------------------------------------------------------

std::string reason(int error) { return std::strerror(error); }

// Writes all of `bytes` to `fd`; false with errno set on failure.
bool write_all(int fd, std::string_view bytes) {
  const char* at = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, at, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    if (n == 0) {
      errno = EIO;
      return false;
    }
    at += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

// So the rename itself survives a power cut. Some file systems refuse fsync on a directory; that
// does not make the file any less complete, so it is not an error.
void sync_directory(const std::string& directory) {
  const int fd = open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd);
  close(fd);
}

std::string directory_of(const std::string& path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

mode_t file_mode() {
  // mkstemp creates the file private (0600); give it the mode a plain fopen would have.
  const mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

}  // namespace

// ---- StagedFile -------------------------------------------------------------------------------

StagedFile::StagedFile(std::string target) : target_(std::move(target)) {
  if (target_.empty()) throw Error("no output file given");
  std::error_code ec;
  const auto status = std::filesystem::status(target_, ec);
  if (std::filesystem::is_directory(status)) throw Error("cannot write " + target_ + ": it is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    // A device or a pipe (/dev/null, /dev/stdout, a FIFO): nothing to stage or rename, the bytes go
    // straight to it. Renaming over it would replace the device with a file.
    fd_ = open(target_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) throw Error("cannot write " + target_ + ": " + reason(errno));
    temp_ = target_;
    direct_ = true;
    return;
  }
  // A symbolic link stays a link: the file it points to is the one replaced.
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(target_, ec)))
    destination_ = std::filesystem::weakly_canonical(target_, ec).string();
  if (destination_.empty()) destination_ = target_;
  std::string pattern = destination_ + ".part-XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  fd_ = mkostemp(name.data(), O_CLOEXEC);
  if (fd_ < 0) throw Error("cannot write " + target_ + ": " + reason(errno));
  fchmod(fd_, file_mode());
  temp_ = name.data();
  slot_ = register_temporary(temp_, kFile);
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)),
      destination_(std::move(other.destination_)),
      temp_(std::move(other.temp_)),
      fd_(std::exchange(other.fd_, -1)),
      slot_(std::exchange(other.slot_, -1)),
      written_(other.written_),
      committed_(std::exchange(other.committed_, true)),
      direct_(other.direct_) {}

StagedFile::~StagedFile() {
  if (!committed_ && !direct_ && !temp_.empty()) std::remove(temp_.c_str());
  release();
}

void StagedFile::release() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
  unregister_temporary(slot_);
  slot_ = -1;
}

void StagedFile::write(std::string_view bytes) {
  if (committed_ || fd_ < 0) throw Error("cannot write " + target_ + ": the file was already committed");
  check_output_size(written_ + bytes.size(), "cannot write " + target_);
  if (!write_all(fd_, bytes)) throw Error("cannot write " + target_ + ": " + reason(errno));
  written_ += bytes.size();
}

void StagedFile::commit() {
  if (committed_) throw Error("cannot write " + target_ + ": the file was already committed");
  if (direct_) {
    committed_ = true;
    const int fd = std::exchange(fd_, -1);
    if (close(fd) != 0) throw Error("cannot write " + target_ + ": " + reason(errno));
    return;
  }
  auto fail = [&](const std::string& what) {
    std::remove(temp_.c_str());
    committed_ = true;  // nothing left to remove
    release();
    throw Error("cannot write " + target_ + ": " + what);
  };
  if (fsync(fd_) != 0) fail(reason(errno));
  const int fd = std::exchange(fd_, -1);
  if (close(fd) != 0) fail(reason(errno));
  if (std::rename(temp_.c_str(), destination_.c_str()) != 0) fail(reason(errno));
  committed_ = true;
  release();
  sync_directory(directory_of(destination_));
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  StagedFile file(path);
  file.write(bytes);
  file.commit();
}

// ---- StagedFileGroup --------------------------------------------------------------------------

StagedFileGroup::StagedFileGroup(std::string directory, std::string label)
    : directory_(directory.empty() ? "." : std::move(directory)), label_(std::move(label)) {
  std::string pattern = (std::filesystem::path(directory_) / ("." + label_ + ".part-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (mkdtemp(name.data()) == nullptr) throw Error("cannot write " + label_ + " in " + directory_ + ": " + reason(errno));
  staging_ = name.data();
  slot_ = register_temporary(staging_, kDirectory);
}

StagedFileGroup::~StagedFileGroup() {
  if (!committed_) remove_staging();
  unregister_temporary(slot_);
}

void StagedFileGroup::remove_staging() {
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
}

void StagedFileGroup::write(const std::string& name, std::string_view bytes) {
  const std::string shown = (std::filesystem::path(directory_) / name).string();
  if (committed_) throw Error("cannot write " + shown + ": the group was already committed");
  if (name.empty() || name.find('/') != std::string::npos) throw Error("cannot write " + shown + ": not a file name");
  check_output_size(bytes.size(), "cannot write " + shown);
  const std::string path = staging_ + "/" + name;
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw Error("cannot write " + shown + ": " + reason(errno));
  const bool ok = write_all(fd, bytes) && fsync(fd) == 0;
  const int error = errno;
  if (close(fd) != 0 || !ok) throw Error("cannot write " + shown + ": " + reason(ok ? errno : error));
  names_.push_back(name);
}

std::vector<std::string> StagedFileGroup::commit() {
  if (committed_) throw Error("cannot write " + label_ + ": the group was already committed");
  std::vector<std::string> written;
  const SignalsHeld held;
  for (const std::string& name : names_) {
    const std::string to = (std::filesystem::path(directory_) / name).string();
    if (std::rename((staging_ + "/" + name).c_str(), to.c_str()) != 0) {
      const std::string why = reason(errno);
      for (const std::string& moved : written) std::remove(moved.c_str());
      remove_staging();
      committed_ = true;
      throw Error("cannot write " + to + ": " + why);
    }
    written.push_back(to);
  }
  committed_ = true;
  rmdir(staging_.c_str());
  unregister_temporary(slot_);
  slot_ = -1;
  sync_directory(directory_);
  return written;
}

// ---- signals ----------------------------------------------------------------------------------

void remove_staged_files_on_signals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int s : kTerminationSignals) {
      struct sigaction previous {};
      sigaction(s, nullptr, &previous);
      if (previous.sa_handler == SIG_IGN) continue;  // e.g. SIGHUP under nohup: leave it ignored
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_die;
      sigemptyset(&action.sa_mask);
      for (int other : kTerminationSignals) sigaddset(&action.sa_mask, other);
      action.sa_flags = SA_RESETHAND;
      sigaction(s, &action, nullptr);
    }
  });
}

}  // namespace gestura
