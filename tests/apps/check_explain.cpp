// Checks what `recode explain` wrote: every picture listed in explain.json exists, is a PNG of
// the listed size and is linked from index.html; the case map's colours give exactly the
// case counts and interfering pixels of the result; the last stencil picture decodes (through
// its palette and core::caseFromStencil) to the same case at every MOR pixel; the silhouettes,
// drawn separately, agree with the cases (interference only where both blocks are); and the
// contact picture highlights exactly the interfering pixels.
//
// With --has-case N, also that case N has pixels (the gallery's pairs are each built to show
// one case).
//
// Usage: recode_check_explain DIR [--has-case N]

#include <stb/stb_image.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "recode/pair/pair_cases.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Rgb = std::array<int, 3>;

int failures = 0;

void fail(const std::string& message) {
  std::cerr << "FAIL: " << message << '\n';
  ++failures;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Width and height from the PNG signature and IHDR chunk, or nullopt if it is not a PNG.
std::optional<std::array<int, 2>> pngHeaderSize(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 24> h{};
  if (!in.read(reinterpret_cast<char*>(h.data()), h.size()))
    return std::nullopt;
  constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  for (std::size_t i = 0; i < kSignature.size(); ++i)
    if (h[i] != kSignature[i])
      return std::nullopt;
  if (h[12] != 'I' || h[13] != 'H' || h[14] != 'D' || h[15] != 'R')
    return std::nullopt;
  const auto be32 = [&](std::size_t at) {
    return static_cast<int>((std::uint32_t{h[at]} << 24) | (std::uint32_t{h[at + 1]} << 16) |
                            (std::uint32_t{h[at + 2]} << 8) | std::uint32_t{h[at + 3]});
  };
  return std::array<int, 2>{be32(16), be32(20)};
}

// A decoded picture and the part of the frame it shows, sampled at framebuffer pixels.
class Picture {
 public:
  Picture(const fs::path& file, const Json& entry) : region_(entry.at("region")) {
    scale_ = entry.at("scale").get<int>();
    unsigned char* data = stbi_load(file.string().c_str(), &width_, &height_, &channels_, 3);
    if (data) {
      pixels_.assign(data, data + 3 * static_cast<std::size_t>(width_) * height_);
      stbi_image_free(data);
    }
  }
  [[nodiscard]] bool ok() const { return !pixels_.empty(); }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] int scale() const { return scale_; }

  // The colour at the centre of framebuffer pixel (x, y) (GL coordinates, y up).
  [[nodiscard]] Rgb at(int x, int y) const {
    const int x0 = region_[0], y1 = region_[3];
    const int px = (x - x0) * scale_ + scale_ / 2;
    const int py = (y1 - 1 - y) * scale_ + scale_ / 2;
    const std::size_t i = 3 * (static_cast<std::size_t>(py) * width_ + px);
    return {pixels_[i], pixels_[i + 1], pixels_[i + 2]};
  }

 private:
  std::array<int, 4> region_;
  int scale_ = 1;
  int width_ = 0;
  int height_ = 0;
  int channels_ = 0;
  std::vector<unsigned char> pixels_;
};

Rgb colourOf(const Json& j) {
  return {j[0].get<int>(), j[1].get<int>(), j[2].get<int>()};
}

std::string text(const Rgb& c) {
  return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
         ")";
}

}  // namespace

int main(int argc, char** argv) {
  const bool hasCaseOption = argc == 4 && std::string(argv[2]) == "--has-case";
  if (argc != 2 && !hasCaseOption) {
    std::cerr << "usage: recode_check_explain DIR [--has-case N]\n";
    return 2;
  }
  const fs::path dir(argv[1]);
  Json j;
  try {
    j = Json::parse(readText(dir / "explain.json"));
  } catch (const std::exception& e) {
    std::cerr << "FAIL: " << (dir / "explain.json").string() << ": " << e.what() << '\n';
    return 1;
  }
  const std::string html = readText(dir / "index.html");
  if (html.find("<!DOCTYPE html>") != 0)
    fail("index.html does not start with <!DOCTYPE html>");

  const int width = j.at("width"), height = j.at("height");
  // The part of the frame the pictures show: within the frame, and holding the MOR.
  const std::array<int, 4> view = j.at("view");
  {
    const std::array<int, 4> m = j.at("mor");
    const bool inFrame = view[0] >= 0 && view[1] >= 0 && view[2] <= width && view[3] <= height &&
                         view[0] < view[2] && view[1] < view[3];
    const bool holdsMor =
        m[2] <= m[0] || (view[0] <= m[0] && view[1] <= m[1] && m[2] <= view[2] && m[3] <= view[3]);
    if (!inFrame || !holdsMor)
      fail("explain.json's view is not a part of the frame holding the MOR");
  }
  std::map<std::string, Picture> byFile;
  const Json* lastStencil = nullptr;
  const Json* cases = nullptr;
  const Json* contact = nullptr;
  const Json* silhouettes = nullptr;
  for (const Json& p : j.at("pictures")) {
    const std::string file = p.at("file");
    const fs::path path = dir / file;
    if (!fs::is_regular_file(path)) {
      fail(file + ": missing");
      continue;
    }
    if (html.find("src=\"" + file + "\"") == std::string::npos)
      fail(file + ": not shown by index.html");
    const auto size = pngHeaderSize(path);
    const std::array<int, 4> region = p.at("region");
    const int scale = p.at("scale");
    const int w = p.at("width"), h = p.at("height");
    if (!size) {
      fail(file + ": not a PNG file");
      continue;
    }
    if ((*size)[0] != w || (*size)[1] != h)
      fail(file + ": PNG is " + std::to_string((*size)[0]) + "x" + std::to_string((*size)[1]) +
           ", explain.json says " + std::to_string(w) + "x" + std::to_string(h));
    if (w != (region[2] - region[0]) * scale || h != (region[3] - region[1]) * scale)
      fail(file + ": size is not the region times the scale");
    Picture picture(path, p);
    if (!picture.ok() || picture.width() != w || picture.height() != h) {
      fail(file + ": stb_image cannot decode it at the listed size");
      continue;
    }
    const bool zoom = p.at("zoom");
    if (zoom)
      continue;
    const std::string kind = p.at("kind");
    if (kind == "overview") {
      if (region != std::array<int, 4>{0, 0, width, height})
        fail(file + ": the overview's region is not the whole frame");
      continue;
    }
    if (region != view)
      fail(file + ": a picture that is not a close-up shows other than the view region");
    if (scale < 3)
      fail(file + ": scale " + std::to_string(scale) +
           " too small to sample pixel centres past the outlines (run with a small resolution)");
    if (kind == "stencil")
      lastStencil = &p;
    else if (kind == "cases")
      cases = &p;
    else if (kind == "contact")
      contact = &p;
    else if (kind == "silhouettes")
      silhouettes = &p;
    byFile.emplace(file, std::move(picture));
  }
  if (failures > 0)
    return 1;

  const std::array<int, 4> mor = j.at("mor");
  const Json& palettes = j.at("palettes");
  std::map<Rgb, int> casePalette, stencilPalette;
  for (int c = 0; c < recode::core::kCaseCount; ++c)
    casePalette[colourOf(palettes.at("cases").at(std::to_string(c)))] = c;
  for (int v = 0; v < 16; ++v)
    stencilPalette[colourOf(palettes.at("stencil").at(std::to_string(v)))] = v;
  if (casePalette.size() != recode::core::kCaseCount || stencilPalette.size() != 16)
    fail("a palette gives two values the same colour");

  if (mor[2] <= mor[0] || mor[3] <= mor[1]) {
    // The box test decided: only the silhouettes, no passes, no collision.
    if (j.at("collide").get<bool>())
      fail("an empty MOR but a collision");
    if (!silhouettes || j.at("sections").size() != 1)
      fail("an empty MOR should give the silhouettes section alone");
    if (failures == 0)
      std::cout << "explain output OK: " << j.at("pictures").size()
                << " pictures; empty MOR, no passes\n";
    return failures == 0 ? 0 : 1;
  }
  if (!cases || !lastStencil || !silhouettes) {
    fail("explain.json lacks the silhouettes, a stencil or the case picture");
    return 1;
  }
  const Picture& casePic = byFile.at(cases->at("file"));
  const Picture& stencilPic = byFile.at(lastStencil->at("file"));
  const Picture& silhouettePic = byFile.at(silhouettes->at("file"));
  const Json& sil = palettes.at("silhouettes");
  const std::map<Rgb, int> coverage = {{colourOf(sil.at("neither")), 0},
                                       {colourOf(sil.at("a")), 1},
                                       {colourOf(sil.at("b")), 2},
                                       {colourOf(sil.at("both")), 3}};

  std::array<long long, recode::core::kCaseCount> counted{};
  long long interfering = 0, decodeMismatches = 0, coverageMismatches = 0;
  for (int y = mor[1]; y < mor[3]; ++y) {
    for (int x = mor[0]; x < mor[2]; ++x) {
      const Rgb cc = casePic.at(x, y);
      const auto c = casePalette.find(cc);
      if (c == casePalette.end()) {
        fail("case map pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") has colour " +
             text(cc) + ", not a case colour");
        return 1;
      }
      ++counted[static_cast<std::size_t>(c->second)];
      interfering += recode::core::isInterfering(c->second) ? 1 : 0;

      const auto s = stencilPalette.find(stencilPic.at(x, y));
      if (s == stencilPalette.end() ||
          recode::core::caseFromStencil(static_cast<std::uint8_t>(s->second)) != c->second)
        ++decodeMismatches;

      const auto cov = coverage.find(silhouettePic.at(x, y));
      const int expected = c->second == 0 ? 0 : c->second == 1 ? 1 : c->second == 8 ? 2 : 3;
      if (cov == coverage.end() || cov->second != expected)
        ++coverageMismatches;
    }
  }
  for (int c = 0; c < recode::core::kCaseCount; ++c) {
    const long long expected = j.at("case_counts").at(std::to_string(c));
    if (counted[static_cast<std::size_t>(c)] != expected)
      fail("case " + std::to_string(c) + ": " +
           std::to_string(counted[static_cast<std::size_t>(c)]) +
           " pixels of its colour in the case map, explain.json says " + std::to_string(expected));
  }
  const long long interferingExpected = j.at("interfering_pixels");
  if (interfering != interferingExpected)
    fail("case map: " + std::to_string(interfering) + " interfering pixels, explain.json says " +
         std::to_string(interferingExpected));
  if (decodeMismatches != 0)
    fail(std::to_string(decodeMismatches) + " MOR pixels whose final stencil (" +
         lastStencil->at("file").get<std::string>() + ") does not decode to the case map's case");
  if (coverageMismatches != 0)
    fail(std::to_string(coverageMismatches) +
         " MOR pixels whose silhouette coverage disagrees with their case");

  if (j.at("collide").get<bool>()) {
    if (!contact) {
      fail("the pair collides but there is no contact picture");
    } else {
      const Picture& contactPic = byFile.at(contact->at("file"));
      const Rgb highlight = colourOf(palettes.at("interfering"));
      long long highlighted = 0;
      for (int y = view[1]; y < view[3]; ++y)
        for (int x = view[0]; x < view[2]; ++x)
          highlighted += contactPic.at(x, y) == highlight ? 1 : 0;
      if (highlighted != interferingExpected)
        fail("contact picture: " + std::to_string(highlighted) +
             " highlighted pixels, explain.json says " + std::to_string(interferingExpected) +
             " interfering");
    }
  }

  if (hasCaseOption) {
    const std::string wanted = argv[3];
    const Json& counts = j.at("case_counts");
    if (!counts.contains(wanted) || counts.at(wanted).get<long long>() <= 0)
      fail("case " + wanted + " has no pixel, the pair was chosen to show it");
  }
  if (failures == 0)
    std::cout << "explain output OK: " << j.at("pictures").size() << " pictures; case map "
              << interfering << " interfering of " << (mor[2] - mor[0]) * (mor[3] - mor[1])
              << " MOR pixels, matching the stencil and the silhouettes\n";
  return failures == 0 ? 0 : 1;
}
