// SPDX-License-Identifier: MIT
#include "bench/lammps_data.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>

#include "support/text_tokens.hpp"

namespace bench {
namespace {

/// A number from a token, or throws naming file and line.
double number(std::string_view token, const std::filesystem::path& file, std::size_t line) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc{} || end != token.data() + token.size()) {
    throw std::runtime_error(fmt::format("{}:{}: '{}' is not a number", file.string(), line, token));
  }
  return v;
}

}  // namespace

LammpsData read_lammps_data(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot open the LAMMPS data file", file.string()));
  LammpsData data;
  std::size_t expected = 0;
  std::unordered_map<std::uint64_t, std::size_t> index;
  enum class Section { header, atoms, velocities, other } section = Section::header;
  std::string text;
  std::size_t line = 0;
  std::size_t velocities = 0;
  while (std::getline(in, text)) {
    ++line;
    if (const auto hash = text.find('#'); hash != std::string::npos && line > 1) text.erase(hash);
    if (line == 1) continue;  // the title line
    const std::vector<std::string_view> t = support::split_words(text);
    if (t.empty()) continue;
    if (t.size() == 1 && (t[0] == "Atoms" || t[0] == "Velocities" || t[0] == "Masses")) {
      section = t[0] == "Atoms" ? Section::atoms : (t[0] == "Velocities" ? Section::velocities : Section::other);
      continue;
    }
    if (t.size() >= 2 && t[0] == "Atoms") {  // "Atoms # sphere"
      section = Section::atoms;
      continue;
    }
    switch (section) {
      case Section::header:
        if (t.size() == 2 && t[1] == "atoms") expected = static_cast<std::size_t>(number(t[0], file, line));
        if (t.size() == 3 && t[1] == "atom" && t[2] == "types") data.atom_types = static_cast<int>(number(t[0], file, line));
        for (int k = 0; k < 3; ++k) {
          static constexpr std::string_view kLo[3] = {"xlo", "ylo", "zlo"};
          if (t.size() == 4 && t[2] == kLo[k]) {
            data.lo[k] = number(t[0], file, line);
            data.hi[k] = number(t[1], file, line);
          }
        }
        break;
      case Section::atoms: {
        if (t.size() != 7 && t.size() != 10) {
          throw std::runtime_error(fmt::format("{}:{}: an atom_style sphere line has 7 or 10 fields, got {}",
                                               file.string(), line, t.size()));
        }
        DataAtom a;
        a.id = static_cast<std::uint64_t>(number(t[0], file, line));
        a.type = static_cast<int>(number(t[1], file, line));
        a.diameter = number(t[2], file, line);
        a.density = number(t[3], file, line);
        a.position = dem::Vec3(number(t[4], file, line), number(t[5], file, line), number(t[6], file, line));
        // Image flags (fields 8–10), when present, only say how often an atom crossed the box
        // before; the run starts from the wrapped position.
        index[a.id] = data.atoms.size();
        data.atoms.push_back(a);
        break;
      }
      case Section::velocities: {
        if (t.size() != 7) {
          throw std::runtime_error(fmt::format("{}:{}: a sphere velocity line has 7 fields, got {}",
                                               file.string(), line, t.size()));
        }
        const auto id = static_cast<std::uint64_t>(number(t[0], file, line));
        const auto it = index.find(id);
        if (it == index.end()) {
          throw std::runtime_error(fmt::format("{}:{}: velocity of unknown atom {}", file.string(), line, id));
        }
        DataAtom& a = data.atoms[it->second];
        a.velocity = dem::Vec3(number(t[1], file, line), number(t[2], file, line), number(t[3], file, line));
        a.angular_velocity = dem::Vec3(number(t[4], file, line), number(t[5], file, line), number(t[6], file, line));
        ++velocities;
        break;
      }
      case Section::other: break;
    }
  }
  if (data.atoms.size() != expected) {
    throw std::runtime_error(fmt::format("{}: the header announces {} atoms, the Atoms section holds {}",
                                         file.string(), expected, data.atoms.size()));
  }
  std::sort(data.atoms.begin(), data.atoms.end(), [](const DataAtom& a, const DataAtom& b) { return a.id < b.id; });
  return data;
}

}  // namespace bench
