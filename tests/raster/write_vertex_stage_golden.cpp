// recode-write-vertex-stage-golden FILE: writes the conformance kit's vertex-stage vectors
// (recode/kit/vertex_stage_vectors.hpp) as the golden file, format recode-vertex-stage-1
// (docs/rasterization.md, section 9). To regenerate after a deliberate change to the vertex
// stage or the vectors:
//   build/tests/raster/recode-write-vertex-stage-golden data/golden/vertex-stage.jsonl
// vertex_stage_vectors_test.cpp checks that the committed file is what this writes.

#include <exception>
#include <fstream>
#include <iostream>
#include <string>

#include "recode/kit/vertex_stage_vectors.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: recode-write-vertex-stage-golden FILE\n";
    return 1;
  }
  try {
    const std::string text = recode::kit::vertexStageGoldenText(recode::kit::vertexStageVectors());
    std::ofstream out(argv[1], std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::cerr << "recode-write-vertex-stage-golden: cannot write " << argv[1] << '\n';
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "recode-write-vertex-stage-golden: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
