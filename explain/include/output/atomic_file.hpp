#pragma once
// Output files written whole or not at all. Every file the programs write (--csv, --write-scene,
// --dump-*, explain's pictures and pages, bench's results) goes through AtomicFile: the bytes go
// to a temporary file beside the target, every write and the close are checked, and commit()
// renames the temporary onto the target. An error, or an exception before commit(), removes
// the temporary, so a failed run leaves neither a partial file nor a stray temporary, and an
// earlier file of that name is kept as it was.
//
// A target that exists and is not a regular file (/dev/stdout, /dev/full, a FIFO) cannot be
// replaced by a rename; it is written directly, still with every write and the close checked.

#include <filesystem>
#include <string>
#include <string_view>

namespace recode::output {

class AtomicFile {
 public:
  // Creates the temporary (or opens the device). `label` names the file in messages, e.g.
  // "--csv out.csv"; empty: the target's path. Throws std::runtime_error naming it.
  explicit AtomicFile(const std::filesystem::path& target, std::string label = "");
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  // Without commit(): removes the temporary.
  ~AtomicFile();

  // Appends bytes (buffered); throws when a write fails.
  void write(std::string_view bytes);
  // Writes what is buffered, closes and renames onto the target; throws on any failure,
  // leaving the target untouched.
  void commit();

 private:
  void flushBuffer();
  [[noreturn]] void fail(const std::string& what, int error);
  void discard();

  std::filesystem::path target_;
  std::filesystem::path temporary_;  // empty when writing a device directly
  std::string label_;
  std::string buffer_;
  int fd_ = -1;
  bool committed_ = false;
};

// The whole file at once.
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes,
                         const std::string& label = "");

// Makes `dir` (and missing parents) for a command's output files. If it did not exist, the
// guard removes it again, with everything written into it, unless keep() is called: a failed
// command leaves no empty or half-filled directory behind.
class CreatedDirectory {
 public:
  // Throws std::runtime_error("<label>: cannot create the directory (...)").
  CreatedDirectory(const std::filesystem::path& dir, const std::string& label);
  CreatedDirectory(const CreatedDirectory&) = delete;
  CreatedDirectory& operator=(const CreatedDirectory&) = delete;
  ~CreatedDirectory();
  void keep() { created_.clear(); }

 private:
  std::filesystem::path created_;  // the outermost directory made here; empty: none
};

}  // namespace recode::output
