// `gkt formula`: print a coefficient's exact closed form (text, LaTeX or C++).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gkt::cli {

/// Returns the closed form of `coefficient` for the scene (model, dimension, order) in `format`
/// ("text", "latex" or "cpp"). Throws std::invalid_argument where no closed form exists.
std::string formula(const std::string& scene_path, const std::vector<std::string>& overrides,
                    const std::string& coefficient, std::optional<int> order, const std::string& format);

}  // namespace gkt::cli
