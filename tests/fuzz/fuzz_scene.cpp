// libFuzzer target: the scene parser and its validation (tools/gkt/scene.cpp), as `gkt table`,
// `gkt stability` and `gkt formula` read a scene. Input: the scene's TOML text; each NUL byte
// starts one --set override (KEY=VALUE) applied to it; an even-length input is read as by gkt
// table (order or tolerance required), an odd one as by gkt formula. Contract: load_scene either
// returns a scene with a registered model and non-empty axes, or throws std::invalid_argument with
// a one-line message — any other exception, crash, leak or sanitizer report is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene.hpp"

namespace {

/// The scene file of this process (load_scene reads a path, as the CLI does).
const std::string& scene_path() {
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("gkt_fuzz_scene_" + std::to_string(::getpid()) + ".toml")).string();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto nul = input.find('\0');
  std::vector<std::string> overrides;
  for (auto at = nul; at != std::string::npos;) {
    const auto next = input.find('\0', at + 1);
    overrides.push_back(input.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
    at = next;
  }
  {
    std::ofstream out(scene_path(), std::ios::binary | std::ios::trunc);
    out << input.substr(0, nul);
  }
  // As gkt table/stability (order or tolerance required) or gkt formula (neither required).
  const bool require_order = size % 2 == 0;
  try {
    const gkt::cli::Scene scene = gkt::cli::load_scene(scene_path(), overrides, require_order);
    // What the front ends rely on: a known model and, per axis, at least one value.
    const auto model = gkt::make_transport_model(scene.model);
    for (const auto& axis : scene.axes)
      if (axis.values.empty()) __builtin_trap();
  } catch (const std::invalid_argument& e) {
    // The one acceptable answer to bad input, printed by gkt as one line naming the field.
    const std::string what = e.what();
    if (what.empty() || what.find('\n') != std::string::npos) __builtin_trap();
  }
  return 0;
}
