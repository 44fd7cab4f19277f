// AtomicFile: mkstemp beside the target, checked writes, checked close, rename.
#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace recode::output {

namespace fs = std::filesystem;

namespace {

// Buffered bytes are written once there are this many.
constexpr std::size_t kBufferBytes = 1 << 16;

std::string withReason(const std::string& what, int error) {
  return error == 0 ? what : what + " (" + std::strerror(error) + ")";
}

}  // namespace

AtomicFile::AtomicFile(const fs::path& target, std::string label)
    : target_(target), label_(label.empty() ? target.string() : std::move(label)) {
  std::error_code ec;
  // Through a symlink: the file it names is replaced, not the link.
  if (fs::is_symlink(fs::symlink_status(target_, ec))) {
    const fs::path resolved = fs::weakly_canonical(target_, ec);
    if (!ec)
      target_ = resolved;
  }
  const fs::file_status status = fs::status(target_, ec);
  if (fs::is_directory(status))
    throw std::runtime_error(label_ + ": is a directory, cannot write a file there");
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or FIFO: written in place (a rename would replace the device node itself).
    fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0)
      fail("cannot open for writing", errno);
    return;
  }
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string(...).
  std::string hidden = ".";
  hidden += target_.filename().string();
  hidden += ".tmp-XXXXXX";
  const std::string pattern = (dir / hidden).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  fd_ = ::mkstemp(name.data());
  if (fd_ < 0)
    fail("cannot create a temporary file in " + dir.string() + " to write it", errno);
  temporary_ = fs::path(name.data());
  // mkstemp makes the file 0600; give it what a plain create would (0666 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd_, 0666 & ~mask) != 0)
    fail("cannot set the temporary file's permissions", errno);
}

AtomicFile::~AtomicFile() {
  if (!committed_)
    discard();
}

void AtomicFile::discard() {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temporary_.empty()) {
    std::error_code ec;
    fs::remove(temporary_, ec);
    temporary_.clear();
  }
}

void AtomicFile::fail(const std::string& what, int error) {
  discard();
  throw std::runtime_error(label_ + ": " + withReason(what, error));
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0)
    throw std::logic_error(label_ + ": write after commit or failure");
  buffer_.append(bytes);
  if (buffer_.size() >= kBufferBytes)
    flushBuffer();
}

void AtomicFile::flushBuffer() {
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      fail("write failed", n < 0 ? errno : ENOSPC);
    done += static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

void AtomicFile::commit() {
  if (fd_ < 0)
    throw std::logic_error(label_ + ": commit after commit or failure");
  flushBuffer();
  const int fd = fd_;
  fd_ = -1;
  // close reports errors a write did not (delayed write-back on network file systems).
  if (::close(fd) != 0)
    fail("write failed on close", errno);
  if (!temporary_.empty()) {
    std::error_code ec;
    fs::rename(temporary_, target_, ec);
    if (ec)
      fail("cannot move the finished file into place: " + ec.message(), 0);
    temporary_.clear();
  }
  committed_ = true;
}

void writeFileAtomically(const fs::path& target, std::string_view bytes, const std::string& label) {
  AtomicFile file(target, label);
  file.write(bytes);
  file.commit();
}

CreatedDirectory::CreatedDirectory(const fs::path& dir, const std::string& label) {
  std::error_code ec;
  // The outermost missing ancestor is what this creates, and what a failure removes.
  fs::path outermost;
  for (fs::path p = dir; !p.empty() && !fs::exists(fs::symlink_status(p, ec));
       p = p.parent_path()) {
    outermost = p;
    if (p == p.parent_path())
      break;
  }
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw std::runtime_error(label + ": cannot create the directory" +
                             (ec ? " (" + ec.message() + ")" : std::string()));
  created_ = outermost;
}

CreatedDirectory::~CreatedDirectory() {
  if (!created_.empty()) {
    std::error_code ec;
    fs::remove_all(created_, ec);
  }
}

}  // namespace recode::output
