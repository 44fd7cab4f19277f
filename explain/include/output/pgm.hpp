#pragma once
// Binary 8-bit PGM output for buffers stored bottom row first (GL order): the file's rows go
// from the top (largest y) down, as image viewers show them.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace recode::output {
void writePgmBottomUp(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& pixels);
}
