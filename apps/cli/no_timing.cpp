#include "cli/no_timing.hpp"

namespace recode::app {

void addNoTimingFlag(CLI::App& cmd, CLI::Option* json, bool& noTiming) {
  cmd.add_flag("--no-timing", noTiming,
               "leave the wall-clock fields out of the JSON, so that two runs print the same bytes")
      ->needs(json);
}

}  // namespace recode::app
