#include "framework/process/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "akvf/error.h"

namespace akvf {

namespace fs = std::filesystem;

namespace {

// Temporary files of writes in progress, kept in fixed storage so that a
// signal handler can read them without allocating. A slot is free (0), being
// filled (1) or names a live temporary (2).
struct PendingSlot {
  std::atomic<int> state{0};
  char path[4096];
};
std::array<PendingSlot, 32> pending;

// Registers `path` for removal on a second signal; -1 if every slot is taken
// (the file is then still removed on every other way out).
int register_pending(const std::string& path) {
  if (path.size() >= sizeof(PendingSlot::path)) return -1;
  for (int i = 0; i < static_cast<int>(pending.size()); ++i) {
    int expected = 0;
    if (!pending[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(pending[i].path, path.c_str(), path.size() + 1);
    pending[i].state.store(2);
    return i;
  }
  return -1;
}

void unregister_pending(int slot) {
  if (slot >= 0) pending[slot].state.store(0);
}

// The file type of `path` without following a last symbolic link; 0 if it
// does not exist.
mode_t file_type(const std::string& path, bool follow) {
  struct stat st;
  const int failed = follow ? ::stat(path.c_str(), &st) : ::lstat(path.c_str(), &st);
  return failed ? 0 : (st.st_mode & S_IFMT);
}

std::string folder_of(const std::string& path) {
  const std::string parent = fs::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

// The longest file name the file system of `folder` takes.
std::size_t name_limit(const std::string& folder) {
  const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  return limit > 0 ? static_cast<std::size_t>(limit) : 255;
}

// Why the last write to a stream failed, as far as errno tells.
std::string write_failure(int error) {
  return error != 0 ? std::strerror(error) : "the write failed (a full disk or a quota?)";
}

// Writes to an existing character device or FIFO in place.
void write_in_place(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw OutputError("cannot write " + path + ": " + std::strerror(errno));
  errno = 0;
  write(out);
  out.flush();
  if (!out) throw OutputError("error while writing " + path + ": " + write_failure(errno));
}

}  // namespace

std::string resolve_output_path(const std::string& path) {
  // A device, FIFO, folder or socket is used as given: /dev/stdout is a
  // chain of links ending in a name like "pipe:[1234]" that only the kernel
  // can open through the link.
  if (const mode_t type = file_type(path, true); type != 0 && type != S_IFREG) return path;
  fs::path current = path;
  for (int hops = 0; file_type(current.string(), false) == S_IFLNK; ++hops) {
    if (hops == 40) throw OutputError("cannot write " + path + ": too many levels of symbolic links");
    std::error_code error;
    const fs::path target = fs::read_symlink(current, error);
    if (error) throw OutputError("cannot write " + path + ": " + error.message());
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  return current.string();
}

bool is_special_output(const std::string& path) {
  const mode_t type = file_type(resolve_output_path(path), true);
  return type != 0 && type != S_IFREG;
}

void check_output_writable(const std::string& path) {
  if (path.empty()) return;
  const std::string target = resolve_output_path(path);
  const std::string shown = target == path ? path : path + " (a link to " + target + ")";
  const mode_t type = file_type(target, true);
  if (type == S_IFDIR) throw OutputError("cannot write " + shown + ": it is a folder; give a file name");
  if (type == S_IFBLK || type == S_IFSOCK)
    throw OutputError("cannot write " + shown + ": it is a " +
                      (type == S_IFBLK ? std::string("block device") : std::string("socket")) +
                      "; give a regular file, a FIFO or a character device");
  if (type != 0 && type != S_IFREG) {  // character device or FIFO: written in place
    if (::access(target.c_str(), W_OK) != 0) throw OutputError("cannot write " + shown + ": " + std::strerror(errno));
    return;
  }
  const std::string folder = folder_of(target);
  if (file_type(folder, true) != S_IFDIR)
    throw OutputError("cannot write " + shown + ": folder " + folder + " does not exist");
  const std::size_t name = fs::path(target).filename().string().size(), limit = name_limit(folder);
  if (name > limit)
    throw OutputError("cannot write " + shown + ": its file name is " + std::to_string(name) +
                      " bytes long; the file system allows at most " + std::to_string(limit));
  if (target.size() >= PATH_MAX)
    throw OutputError("cannot write " + shown + ": the path is " + std::to_string(target.size()) +
                      " bytes long; the system allows at most " + std::to_string(PATH_MAX - 1));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw OutputError("cannot write " + shown + ": folder " + folder + " is not writable (" + std::strerror(errno) +
                      ")");
  if (type == S_IFREG && ::access(target.c_str(), W_OK) != 0)
    throw OutputError("cannot write " + shown + ": the existing file is not writable (" + std::strerror(errno) + ")");
}

std::string sibling_path(const std::string& path, const std::string& suffix) {
  const fs::path file(path);
  std::string name = file.filename().string();
  const std::size_t limit = name_limit(folder_of(path));
  if (name.size() + suffix.size() > limit) name.resize(limit > suffix.size() ? limit - suffix.size() : 0);
  return (file.parent_path() / (name + suffix)).string();
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string target = resolve_output_path(path);
  const mode_t type = file_type(target, true);
  if (type == S_IFDIR) throw OutputError("cannot write " + path + ": it is a folder");
  if (type != 0 && type != S_IFREG) return write_in_place(target, write);

  const std::string temporary = sibling_path(target, ".tmp" + std::to_string(::getpid()));
  const int slot = register_pending(temporary);
  auto discard = [&] {
    std::remove(temporary.c_str());
    unregister_pending(slot);
  };
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) {
      const std::string reason = std::strerror(errno);
      unregister_pending(slot);
      throw OutputError("cannot write " + path + ": " + reason);
    }
    errno = 0;
    try {
      write(out);
      out.flush();
    } catch (...) {
      out.close();
      discard();
      throw;
    }
    if (out) out.close();  // a failure to write the last buffer shows here
    const int error = errno;
    if (!out) {
      discard();
      throw OutputError("error while writing " + path + ": " + write_failure(error));
    }
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    discard();
    throw OutputError("cannot move " + temporary + " to " + target + ": " + reason);
  }
  unregister_pending(slot);
}

void remove_pending_temporary_files() noexcept {
  for (PendingSlot& slot : pending)
    if (slot.state.load() == 2) ::unlink(slot.path);
}

void create_output_folder(const std::string& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw OutputError("cannot create the output folder " + folder + ": " + error.message());
  if (!std::filesystem::is_directory(folder))
    throw OutputError("cannot use " + folder + " as the output folder: it is not a folder");
}

}  // namespace akvf
