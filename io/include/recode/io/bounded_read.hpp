#pragma once
// Reading a user's file whole, with a bound. A file named on the command line or in a scene can
// be anything: /dev/zero, a FIFO that never ends, a directory, a symlink to either, or a huge
// file. Reading one of those "whole" hangs or exhausts memory, so every reader goes through
// readBoundedFile, which refuses anything but a regular file and any file over a limit before
// reading a byte.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace recode::io {

// The limits (docs/architecture.md, "Files read"). Generous for real inputs: the largest mesh
// in data/ is a few MB, a scene or command stream a few hundred kB, a golden vector a few MB.
inline constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
inline constexpr std::uint64_t kMaxJsonFileBytes = 64 * kMiB;
inline constexpr std::uint64_t kMaxMeshFileBytes = 1024 * kMiB;

// A file that cannot be read: file() is the path as given, problem() what is wrong, what()
// "<file>: <problem>". Each layer rethrows the problem in its own error type (MeshError,
// SceneError, FormatError).
class FileReadError : public std::runtime_error {
 public:
  FileReadError(const std::string& file, const std::string& problem);
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::string problem_;
};

// The contents of `path`. `kind` names the file in messages ("scene file", "mesh file"). Throws
// FileReadError, with problem "cannot read <kind>: <reason>", when the path does not exist, is
// not a regular file after following symlinks (a directory, a device, a FIFO, a socket), cannot
// be opened, is larger than maxBytes (the reason gives its size and the limit), or a read fails.
// A FIFO is recognised without opening it, so it cannot block.
[[nodiscard]] std::string readBoundedFile(const std::filesystem::path& path, std::uint64_t maxBytes,
                                          std::string_view kind);

// A byte count for messages: "67108864 bytes (64 MiB)"; whole KiB, MiB and GiB are named, other
// sizes are given with one decimal ("1.5 GiB").
[[nodiscard]] std::string describeBytes(std::uint64_t bytes);

}  // namespace recode::io
