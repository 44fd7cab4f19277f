// readBoundedFile: stat, refuse, open without blocking, check again, read at most the limit.
#include "recode/io/bounded_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace recode::io {

FileReadError::FileReadError(const std::string& file, const std::string& problem)
    : std::runtime_error(file + ": " + problem), file_(file), problem_(problem) {}

std::string describeBytes(std::uint64_t bytes) {
  std::string text = std::to_string(bytes) + " byte" + (bytes == 1 ? "" : "s");
  constexpr const char* kUnits[] = {"GiB", "MiB", "KiB"};
  for (int i = 0; i < 3; ++i) {
    const std::uint64_t unit = std::uint64_t{1} << (10 * (3 - i));
    if (bytes < unit)
      continue;
    char scaled[64];
    if (bytes % unit == 0)
      std::snprintf(scaled, sizeof scaled, "%llu %s", static_cast<unsigned long long>(bytes / unit),
                    kUnits[i]);
    else
      std::snprintf(scaled, sizeof scaled, "%.1f %s",
                    static_cast<double>(bytes) / static_cast<double>(unit), kUnits[i]);
    return text + " (" + scaled + ")";
  }
  return text;
}

namespace {

// What a non-regular file is, for the message.
const char* fileType(mode_t mode) {
  if (S_ISDIR(mode))
    return "it is a directory";
  if (S_ISCHR(mode))
    return "it is not a regular file (a character device)";
  if (S_ISBLK(mode))
    return "it is not a regular file (a block device)";
  if (S_ISFIFO(mode))
    return "it is not a regular file (a FIFO)";
  if (S_ISSOCK(mode))
    return "it is not a regular file (a socket)";
  return "it is not a regular file";
}

// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0)
      ::close(fd);
  }
};

}  // namespace

std::string readBoundedFile(const std::filesystem::path& path, std::uint64_t maxBytes,
                            std::string_view kind) {
  const std::string name = path.string();
  const std::string prefix = "cannot read " + std::string(kind) + ": ";
  const auto fail = [&](const std::string& reason) -> void {
    throw FileReadError(name, prefix + reason);
  };
  const auto check = [&](const struct stat& st) {
    if (!S_ISREG(st.st_mode))
      fail(fileType(st.st_mode));
    const auto size = static_cast<std::uint64_t>(st.st_size);
    if (size > maxBytes)
      fail("it is " + describeBytes(size) + ", over the limit of " + describeBytes(maxBytes) +
           " for a " + std::string(kind));
  };

  // stat first (it follows symlinks): a FIFO or device is refused before open could block on it.
  struct stat st {};
  if (::stat(name.c_str(), &st) != 0)
    fail(errno == ENOENT ? std::string("file not found") : std::strerror(errno));
  check(st);
  // O_NONBLOCK: should the path have become a FIFO since, open does not wait for a writer.
  Descriptor file{::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0)
    fail(std::string("cannot open it (") + std::strerror(errno) + ")");
  if (::fstat(file.fd, &st) != 0)
    fail(std::strerror(errno));
  check(st);  // what was opened, which is what is read

  // Read until the end, but never more than the limit: a file that grows while it is read is
  // refused too.
  std::string contents;
  contents.resize(static_cast<std::size_t>(st.st_size));
  std::size_t used = 0;
  for (;;) {
    if (used == contents.size()) {
      if (contents.size() >= maxBytes + 1)
        break;
      contents.resize(static_cast<std::size_t>(
          std::min<std::uint64_t>(maxBytes + 1, contents.size() + 64 * 1024)));
    }
    const ssize_t n = ::read(file.fd, contents.data() + used, contents.size() - used);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      fail(std::string("read error (") + std::strerror(errno) + ")");
    }
    if (n == 0)
      break;
    used += static_cast<std::size_t>(n);
  }
  if (used > maxBytes)
    fail("it grew past the limit of " + describeBytes(maxBytes) + " for a " + std::string(kind) +
         " while it was read");
  contents.resize(used);
  return contents;
}

}  // namespace recode::io
