// Replays every golden vector of data/golden/ (the hand-made ones and the conformance kit in
// data/golden/kit/) on the CPU device and on the independent per-pixel model: both must
// reproduce the stored buffers bit for bit. Also checks that the
// golden reader reports malformed files with the JSON path of the problem, in the notation of
// scene files.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "recode/kit/reference_model.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"

using namespace recode::raster;

TEST_CASE("golden vectors replay bit for bit on the CPU device and the model", "[golden]") {
  const std::filesystem::path dir = std::filesystem::path(RECODE_DATA_DIR) / "golden";
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".json")
      continue;
    ++files;
    const GoldenVector g = readGolden(entry.path());
    INFO(entry.path().filename().string() << ": " << g.description);
    CpuDevice dev(g.stream.width, g.stream.height);
    replay(g.stream.commands, dev);
    const auto depth = dev.depthBuffer();
    const auto stencil = dev.stencilBuffer();
    CHECK(std::vector<std::uint32_t>(depth.begin(), depth.end()) == g.depth);
    CHECK(std::vector<std::uint8_t>(stencil.begin(), stencil.end()) == g.stencil);

    recode::kit::ReferenceModel model(g.stream.width, g.stream.height);
    model.run(g.stream.commands);
    CHECK(model.depthBuffer() == g.depth);
    CHECK(model.stencilBuffer() == g.stencil);

    // Every golden vector must exercise something: some pixel differs from the defaults.
    bool touched = false;
    for (std::size_t i = 0; i < g.stencil.size(); ++i) {
      touched = touched || g.stencil[i] != 0 || g.depth[i] != kDepthMax;
    }
    CHECK(touched);

    // Writing and reading back is lossless.
    const GoldenVector again = goldenFromJson(goldenToJson(g), "round-trip");
    CHECK(again.depth == g.depth);
    CHECK(again.stencil == g.stencil);
    CHECK(commandStreamToJson(again.stream) == commandStreamToJson(g.stream));
  }
  CHECK(files >= 7 + 200);
}

TEST_CASE("malformed golden and command files name the JSON path", "[golden]") {
  const std::string head = R"({"format": "recode-commands-1", "width": 4, "height": 4, )";
  CHECK_THROWS_WITH(commandStreamFromJson(head + R"("commands": [{"op": "depth_func",
      "func": "LESSER"}]})",
                                          "x.json"),
                    Catch::Equals("x.json: commands[0].func: unknown compare function \"LESSER\""));
  CHECK_THROWS_WITH(
      commandStreamFromJson(head + R"("commands": [{"op": "draw",
      "vertices_fixed": [[0, 0, 0.5], [256, 0, 0.5]], "indices": [0, 1, 2]}]})",
                            "y.json"),
      Catch::Equals("y.json: commands[0].indices[2]: expected an integer in 0..1, got 2"));
  CHECK_THROWS_WITH(
      commandStreamFromJson(head + R"("commands": [{"op": "clear_stencil",
      "value": 300}]})",
                            "z.json"),
      Catch::Equals("z.json: commands[0].value: expected an integer in 0..255, got 300"));
  CHECK_THROWS_WITH(commandStreamFromJson(head + R"("commands": [{"op": "cull", "mode": "none",
      "colour": 1}]})",
                                          "k.json"),
                    Catch::Equals("k.json: commands[0].colour: unknown key (allowed: op, mode)"));
  CHECK_THROWS_WITH(commandStreamFromJson(head + R"("commands": [{"op": "blend"}]})", "b.json"),
                    Catch::Equals("b.json: commands[0].op: unknown command \"blend\""));
  CHECK_THROWS_WITH(commandStreamFromJson(R"({"format": "recode-commands-1", "width": 0,
      "height": 4, "commands": []})",
                                          "w.json"),
                    Catch::Equals("w.json: width: expected an integer in 1..16384, got 0"));
  CHECK_THROWS_WITH(commandStreamFromJson("{\"format\": ", "t.json"),
                    Catch::StartsWith("t.json:1:12: invalid JSON: "));
  CHECK_THROWS_WITH(
      commandStreamFromJson(head + R"("commands": [{"op": "draw",
      "vertices_fixed": [[0, 0, 0.1]], "indices": []}]})",
                            "f.json"),
      Catch::Equals(
          "f.json: commands[0].vertices_fixed[0][2]: depth is not a single-precision float"));
  // The top level, a key that is not an identifier and a repeated key, as the JSON reading
  // layer shows them for scene files too.
  CHECK_THROWS_WITH(commandStreamFromJson("[1, 2]", "r.json"),
                    Catch::Equals("r.json: (root): expected an object, got an array"));
  CHECK_THROWS_WITH(
      commandStreamFromJson(R"({"format": "recode-commands-1", "my key": 1})", "q.json"),
      Catch::Equals(
          "q.json: [\"my key\"]: unknown key (allowed: format, width, height, commands)"));
  CHECK_THROWS_WITH(commandStreamFromJson(head + R"("commands": [], "width": 5})", "d.json"),
                    Catch::Equals("d.json: width: duplicate key"));
  try {
    (void)commandStreamFromJson(head + R"("commands": [{"op": "depth_func", "func": 1}]})",
                                "e.json");
    FAIL("no FormatError");
  } catch (const FormatError& e) {
    CHECK(e.file() == "e.json");
    CHECK(e.jsonPath() == "commands[0].func");
  }
  CHECK_THROWS_WITH(readGolden("/nonexistent/golden.json"),
                    Catch::Equals("/nonexistent/golden.json: cannot read golden vector or "
                                  "command stream: file not found"));
  CHECK_THROWS_WITH(readCommandFile("/dev/zero"),
                    Catch::Equals("/dev/zero: cannot read golden vector or command stream: it is "
                                  "not a regular file (a character device)"));
}

TEST_CASE("readCommandFile chooses the format by its format key", "[golden]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const GoldenVector golden =
      readGolden(std::filesystem::path(RECODE_DATA_DIR) / "golden" / "fill_square.json");
  const CommandFile asGolden =
      readCommandFile(std::filesystem::path(RECODE_DATA_DIR) / "golden" / "fill_square.json");
  CHECK(asGolden.hasExpected);
  CHECK(asGolden.content.stencil == golden.stencil);

  const std::filesystem::path streamPath = dir / "recode_stream_test.json";
  {
    std::ofstream out(streamPath);
    out << commandStreamToJson(golden.stream);
  }
  const CommandFile asStream = readCommandFile(streamPath);
  CHECK_FALSE(asStream.hasExpected);
  CHECK(asStream.content.stencil.empty());
  CHECK(commandStreamToJson(asStream.content.stream) == commandStreamToJson(golden.stream));

  const std::filesystem::path badPath = dir / "recode_bad_format_test.json";
  {
    std::ofstream out(badPath);
    out << R"({"format": "recode-golden-2"})";
  }
  CHECK_THROWS_WITH(
      readCommandFile(badPath),
      Catch::EndsWith("recode_bad_format_test.json: format: expected \"recode-golden-1\" or "
                      "\"recode-commands-1\", got \"recode-golden-2\""));
  std::filesystem::remove(streamPath);
  std::filesystem::remove(badPath);
}
