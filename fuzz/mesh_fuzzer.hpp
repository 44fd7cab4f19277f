#pragma once
// The mesh readers take paths, so each input is written to a file in /dev/shm (memory, not
// disk) named with the extension that picks the reader, then read back through readMesh.

#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <string>

#include "fuzz_support.hpp"
#include "recode/geometry/mesh_io.hpp"

namespace recode::fuzz {

inline void readMeshText(std::string_view text, const char* extension) {
  static const std::string path = "/dev/shm/recode-fuzz-" + std::to_string(::getpid()) + extension;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  expectCleanErrors([&] { (void)core::readMesh(path); });
}

}  // namespace recode::fuzz
