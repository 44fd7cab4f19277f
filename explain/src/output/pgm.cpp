#include "output/pgm.hpp"

#include <string>

#include "output/atomic_file.hpp"

namespace recode::output {

void writePgmBottomUp(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& pixels) {
  AtomicFile out(path);
  out.write("P5\n" + std::to_string(width) + ' ' + std::to_string(height) + "\n255\n");
  for (int y = height - 1; y >= 0; --y) {
    out.write(
        {reinterpret_cast<const char*>(pixels.data()) + static_cast<std::ptrdiff_t>(y) * width,
         static_cast<std::size_t>(width)});
  }
  out.commit();
}

}  // namespace recode::output
