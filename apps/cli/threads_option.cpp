#include "cli/threads_option.hpp"

#include <charconv>
#include <string>

namespace recode::app {

namespace {

// CLI11 would read "2.5" or "-1" into an int with a message about conversion; say what is
// wanted instead. The upper bound only keeps the number an int: TBB caps it at the machine.
const CLI::Validator kThreadCount(
    [](std::string& text) -> std::string {
      int value = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (error != std::errc() || end != text.data() + text.size() || value < 0)
        return "expected 0 (all hardware threads) or a positive number of threads, got " + text;
      return "";
    },
    "N");

}  // namespace

CLI::Option* addThreadsOption(CLI::App& cmd, int& threads) {
  return cmd
      .add_option("--threads", threads,
                  "threads for each frame's pair tests on the CPU device: 0 all hardware "
                  "threads (default), 1 sequential, N at most N; the results are the same "
                  "bytes for any N")
      ->check(kThreadCount);
}

}  // namespace recode::app
