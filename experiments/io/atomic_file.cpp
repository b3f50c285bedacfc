// Atomic output files; see atomic_file.hpp.
#include "experiments/io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "experiments/io/file_descriptor.hpp"

namespace rice::experiments {

namespace {

namespace fs = std::filesystem;

// The marker in the names of the temporaries of the named fallback: `.<name>.partial-<pid>-<n>`.
constexpr std::string_view kPartial = ".partial-";

[[noreturn]] void fail_write(const fs::path& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path.string() + ": " + what + ": " + std::strerror(errno));
}

void write_all(int fd, std::string_view bytes, const fs::path& path) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail_write(path, "write");
    bytes.remove_prefix(static_cast<size_t>(written));
  }
}

// Gives the unnamed file open as `fd` the name `path`. linkat cannot replace a name, so an
// existing file is unlinked and the link tried again: `path` is absent for that moment, never
// partial, and no other name ever exists. False where linking is impossible (/proc not
// mounted, a file system that refuses) or another process keeps recreating `path`.
bool link_into_place(int fd, const fs::path& path) {
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  for (int attempt = 0; attempt < 100; ++attempt) {
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW) == 0) return true;
    if (errno != EEXIST) return false;
    if (::unlink(path.c_str()) != 0 && errno != ENOENT) return false;
  }
  return false;
}

// Writes `bytes` to an unnamed file in `folder` (Linux O_TMPFILE) and links it as `path` once
// complete. False, with `path` untouched or absent, where the folder cannot hold unnamed files
// or linking fails; write errors throw.
bool write_unnamed(const fs::path& folder, const fs::path& path, std::string_view bytes) {
  const int fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  // Not checked at close: the file systems with O_TMPFILE are local and report errors at write.
  const FileDescriptor closed(fd);
  write_all(fd, bytes, path);
  return link_into_place(fd, path);
}

// The fallback: a hidden named temporary renamed into place. A SIGKILL can leave the
// temporary behind (never a partial `path`); make_output_folder removes such leftovers.
void write_named_temporary(const fs::path& folder, const fs::path& path, std::string_view bytes) {
  static std::atomic<unsigned> counter = 0;
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string hidden = ".";
  for (const std::string& piece : {path.filename().string(), std::string(kPartial), std::to_string(::getpid()),
                                   std::string("-"), std::to_string(counter++)})
    hidden += piece;
  const fs::path temporary = folder / hidden;
  int fd = ::open(temporary.c_str(), O_CREAT | O_TRUNC | O_WRONLY | O_CLOEXEC, 0644);
  if (fd < 0) fail_write(path, "open");
  try {
    write_all(fd, bytes, path);
    if (::close(std::exchange(fd, -1)) != 0) fail_write(path, "close");
    if (std::rename(temporary.c_str(), path.c_str()) != 0) fail_write(path, "rename");
  } catch (...) {
    if (fd >= 0) ::close(fd);
    ::unlink(temporary.c_str());
    throw;
  }
}

// The process that wrote the temporary called `name` (`.<name>.partial-<pid>-<n>`); 0 when
// `name` is not such a temporary.
pid_t writer_of_temporary(std::string_view name) {
  const size_t at = name.rfind(kPartial);
  if (!name.starts_with('.') || at == std::string_view::npos) return 0;
  const std::string_view rest = name.substr(at + kPartial.size());
  pid_t pid = 0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
  if (error != std::errc{} || end == rest.data() + rest.size() || *end != '-') return 0;
  return pid;
}

// Removes the temporaries that killed runs left in `folder`: those of processes that are gone,
// and of this process (which prepares a folder before writing into it). A live run's
// temporaries, in flight, stay.
void remove_stale_temporaries(const fs::path& folder) {
  std::error_code error;  // best effort: a leftover is only clutter
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const pid_t writer = writer_of_temporary(entry.path().filename().string());
    const bool gone = writer > 0 && (writer == ::getpid() || (::kill(writer, 0) != 0 && errno == ESRCH));
    if (gone && entry.is_regular_file(error)) fs::remove(entry.path(), error);
  }
}

}  // namespace

void make_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw std::runtime_error("cannot create output folder " + folder.string() + ": " + error.message());
  remove_stale_temporaries(folder);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  // The named temporary only where an unnamed file cannot be made or linked.
  if (!write_unnamed(folder, path, bytes)) write_named_temporary(folder, path, bytes);
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream out;
  write(out);
  write_file_atomically(path, out.view());
}

}  // namespace rice::experiments
