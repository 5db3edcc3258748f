// SPDX-License-Identifier: MIT
#include "sweeps/case_override.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cases/case_loader.hpp"

namespace sweeps {
namespace {

/// One step of a dotted key: a table entry, optionally indexed into an array ("stages[0]").
struct Step {
  std::string name;
  std::optional<std::size_t> index;
};

std::vector<Step> parse_key(const std::string& key, const std::string& path) {
  std::vector<Step> out;
  std::size_t start = 0;
  while (start <= key.size()) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    Step s;
    const std::size_t open = part.find('[');
    if (open == std::string::npos) {
      s.name = part;
    } else {
      const std::size_t close = part.find(']', open);
      if (close != part.size() - 1 || close == open + 1) {
        throw cases::CaseError(path, key, "malformed index (expected NAME[INDEX])");
      }
      s.name = part.substr(0, open);
      try {
        s.index = static_cast<std::size_t>(std::stoull(part.substr(open + 1, close - open - 1)));
      } catch (const std::exception&) {
        throw cases::CaseError(path, key, "malformed index (expected NAME[INDEX])");
      }
    }
    if (s.name.empty()) throw cases::CaseError(path, key, "empty part in the key");
    out.push_back(s);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return out;
}

/// The node `key` names in `root`; throws naming the key when a part is absent.
toml::node& find_node(toml::table& root, const std::string& key, const std::string& path) {
  toml::node* node = &root;
  std::string walked;
  for (const Step& s : parse_key(key, path)) {
    walked += (walked.empty() ? "" : ".") + s.name;
    toml::table* table = node->as_table();
    toml::node* next = table != nullptr ? table->get(s.name) : nullptr;
    if (next == nullptr) throw cases::CaseError(path, key, fmt::format("the case has no '{}' to sweep", walked));
    if (s.index) {
      toml::array* array = next->as_array();
      if (array == nullptr || *s.index >= array->size()) {
        throw cases::CaseError(path, key, fmt::format("the case has no '{}[{}]' to sweep", walked, *s.index));
      }
      walked += fmt::format("[{}]", *s.index);
      next = array->get(*s.index);
    }
    node = next;
  }
  return *node;
}

/// Replaces the number at `node` by `value` (integer where it was one and value is integral).
void set_number(toml::node& node, double value, const std::string& key, const std::string& path) {
  if (!std::isfinite(value)) throw cases::CaseError(path, key, fmt::format("swept value {} is not finite", value));
  if (auto* i = node.as_integer()) {
    if (value != std::floor(value) || std::abs(value) > 9.0e15) {
      throw cases::CaseError(path, key, fmt::format("holds an integer; {} is not one", value));
    }
    *i = static_cast<std::int64_t>(value);
    return;
  }
  if (auto* f = node.as_floating_point()) {
    *f = value;
    return;
  }
  throw cases::CaseError(path, key, "holds no number to sweep (sweep numbers only)");
}

/// Replaces the value at `node` by a fixed setting's, which must be of the same kind.
void set_fixed(toml::node& node, const FixedSetting& f, const std::string& path) {
  if (const auto* number = std::get_if<double>(&f.value)) {
    if (!node.is_number()) throw cases::CaseError(path, f.key, "holds no number; the sweep sets one");
    set_number(node, *number, f.key, path);
    return;
  }
  if (const auto* flag = std::get_if<bool>(&f.value)) {
    auto* b = node.as_boolean();
    if (b == nullptr) throw cases::CaseError(path, f.key, "holds no boolean; the sweep sets one");
    *b = *flag;
    return;
  }
  auto* str = node.as_string();
  if (str == nullptr) throw cases::CaseError(path, f.key, "holds no string; the sweep sets one");
  *str = std::get<std::string>(f.value);
}

}  // namespace

std::string override_case(std::string_view text, const std::string& path,
                          const std::vector<std::pair<std::string, double>>& values, std::optional<std::uint64_t> seed,
                          const std::vector<FixedSetting>& fixed) {
  toml::table root;
  try {
    root = toml::parse(text, std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw cases::CaseError(path, "(syntax)", std::string(e.description()), static_cast<int>(e.source().begin.line),
                           static_cast<int>(e.source().begin.column));
  }
  for (const FixedSetting& f : fixed) set_fixed(find_node(root, f.key, path), f, path);
  for (const auto& [key, value] : values) set_number(find_node(root, key, path), value, key, path);
  if (seed) {
    toml::array* populations = root["populations"].as_array();
    if (populations == nullptr || populations->empty()) {
      throw cases::CaseError(path, "populations", "sweep seeds need [[populations]] to seed");
    }
    for (std::size_t k = 0; k < populations->size(); ++k) {
      toml::table* p = populations->get(k)->as_table();
      if (p == nullptr) throw cases::CaseError(path, fmt::format("populations[{}]", k), "expected a table");
      p->insert_or_assign("seed", static_cast<std::int64_t>(*seed + k));
    }
  }
  std::ostringstream out;
  out << root << '\n';
  return out.str();
}

}  // namespace sweeps
