#include "pgm.hpp"

#include <fstream>
#include <stdexcept>

namespace recode::app {

void writePgmBottomUp(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& pixels) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw std::runtime_error(path.string() + ": cannot open for writing");
  out << "P5\n" << width << ' ' << height << "\n255\n";
  for (int y = height - 1; y >= 0; --y) {
    out.write(reinterpret_cast<const char*>(pixels.data()) + static_cast<std::ptrdiff_t>(y) * width,
              width);
  }
  if (!out)
    throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace recode::app
