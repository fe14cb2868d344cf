// libFuzzer target: the experiment-manifest parser (JSON, then the schema of
// docs/experiments.md: names, numbers, key paths in every error).
#include "experiments/runner/manifest.h"
#include "tests/fuzz/fuzz_text_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::run_on_text(data, size, [](const std::string& text) { akvf::parse_manifest(text, "fuzz.json"); });
}
