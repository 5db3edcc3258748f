// SPDX-License-Identifier: MIT
// A corpus of injection payloads (newline + LAMMPS `shell`, `"""`, $(…), ${…}, &, #, backticks,
// Python quotes, markdown/HTML) put into every string of a case with a wall, run through the real
// LAMMPS, YADE and LIGGGHTS. Each one is either refused at load time naming its key, or runs with the same
// trace as the untouched case: no command runs, no deck or script changes meaning, and report.md
// shows the text inert.
#include <functional>
#include <regex>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "support/process.hpp"
#include "tests/app/demwb_process.hpp"

namespace payload_corpus_test {

using demwb_e2e::canonical;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

/// A TOML basic string holding `text` exactly.
std::string toml_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

/// The payloads; SENTINEL is replaced by a file that must never come to exist.
std::vector<std::string> payloads(const std::string& sentinel) {
  std::vector<std::string> p = {
      "floor\nshell touch SENTINEL\n#",
      "floor\r\nshell touch SENTINEL",
      "x\"\"\"\nimport os; os.system('touch SENTINEL')\n\"\"\"",
      "x'''\nimport os; os.system('touch SENTINEL')\n'''",
      "'); import os; os.system('touch SENTINEL'); ('",
      "\"); __import__('os').system('touch SENTINEL'); (\"",
      "$(touch SENTINEL)",
      "${shell touch SENTINEL}",
      "`touch SENTINEL`",
      "a & touch SENTINEL &",
      "# next line\nvariable x equal 1\nrun 0",
      "<script>alert('x')</script> [link](javascript:alert(1)) ![img](http://example.invalid/x.png) | a | b |\n# heading",
      std::string("nul\x01\x1b[31m red \x7f end"),
  };
  for (auto& s : p) s = std::regex_replace(s, std::regex("SENTINEL"), sentinel);
  return p;
}

/// One place a string goes in the template: the text to find and how to write the payload there.
struct Site {
  std::string key;
  std::string find;
  std::function<std::string(const std::string&)> put;  ///< TOML replacing `find`, from the quoted payload
};

std::vector<Site> sites() {
  return {
      {"case.name", "name = \"oblique_wall_impact\"", [](const std::string& q) { return "name = " + q; }},
      // The two free-text keys take each payload together: every payload is accepted there and runs
      // both codes, so one run per payload serves both keys.
      {"case.description", "description = \"Sphere hits",
       [](const std::string& q) { return "description = " + q + "\nx_was = \"Sphere hits"; }},
      {"model.normal", "normal = \"linear\"", [](const std::string& q) { return "normal = " + q; }},
      {"model.friction_limit", "friction_limit = \"total\"", [](const std::string& q) { return "friction_limit = " + q; }},
      {"materials.<name>", "[materials.sphere]", [](const std::string& q) { return "[materials." + q + "]"; }},
      {"walls.type", "type = \"plane\"", [](const std::string& q) { return "type = " + q; }},
      {"walls.name", "name = \"floor\"", [](const std::string& q) { return "name = " + q; }},
      {"walls.material", "point = [0.0, 0.0, 0.0]", [](const std::string& q) { return "point = [0.0, 0.0, 0.0]\nmaterial = " + q; }},
      {"integration.scheme", "scheme = \"velocity_verlet\"", [](const std::string& q) { return "scheme = " + q; }},
      {"compare.engines", "engines = [\"inhouse\", \"analytic\", \"lammps\", \"yade\", \"liggghts\"]",
       [](const std::string& q) {
         return "engines = [\"inhouse\", \"analytic\", \"lammps\", \"yade\", \"liggghts\", " + q + "]";
       }},
      {"compare.reference", "reference = \"analytic\"", [](const std::string& q) { return "reference = " + q; }},
      {"compare.metrics", "metrics = [\"contact_duration\"", [](const std::string& q) { return "metrics = [" + q + ", \"contact_duration\""; }},
  };
}

/// The template: oblique_wall_impact without its matched runs (the corpus needs the codes, not the
/// core in their numerics) and without the placeholder keys the description/thesis sites add.
std::string template_case() {
  std::string text = support::read_file(canonical("oblique_wall_impact"));
  text = std::regex_replace(text, std::regex("\nmatched = [^\n]*"), "");
  return text;
}

/// Every file under `dir` whose name is `name`, concatenated.
std::string files_named(const fs::path& dir, const std::string& name) {
  std::string all;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec)) {
    if (e.path().filename() == name) all += support::read_file(e.path());
  }
  return all;
}

TEST(PayloadCorpus, NoPayloadInAnyStringRunsACommandOrChangesARun) {
  if (!support::find_program("lmp") || !support::find_program("yade") || !support::find_program("liggghts")) {
    GTEST_SKIP() << "needs LAMMPS, YADE and LIGGGHTS (scripts/setup.sh installs them)";
  }
  const fs::path root = scratch("payloads");
  fs::create_directories(root);
  const fs::path sentinel = root / "SENTINEL-was-created";
  const std::string base = template_case();
  // The untouched case: the traces every accepted payload must reproduce. The time-step check
  // (reruns at Δt/2, …) would only multiply the runs; the strings are what is under test.
  support::write_file(root / "base.toml", base);
  const auto neutral = demwb({"run", (root / "base.toml").string(), "--engine", "lammps,yade,liggghts", "--no-cache", "--no-time-step-check", "-o",
                              (root / "base").string()});
  ASSERT_NE(neutral.exit_code, 2) << neutral.err;
  const std::string lammps_trace = support::read_file(root / "base" / "trace_lammps.csv");
  const std::string yade_trace = support::read_file(root / "base" / "trace_yade.csv");
  const std::string liggghts_trace = support::read_file(root / "base" / "trace_liggghts.csv");

  int refused = 0;
  int ran = 0;
  int n = 0;
  for (const Site& site : sites()) {
    const auto at = base.find(site.find);
    ASSERT_NE(at, std::string::npos) << site.key << ": the template has no " << site.find;
    for (const std::string& payload : payloads(sentinel.string())) {
      const std::string label = fmt::format("{} #{}", site.key, n);
      const fs::path file = root / fmt::format("case{}.toml", n);
      const fs::path out = root / fmt::format("out{}", n++);
      std::string text = base;
      text.replace(at, site.find.size(), site.put(toml_string(payload)));
      if (site.key == "case.description") {
        text = std::regex_replace(text, std::regex("\nx_was = [^\n]*"), "");
        const auto thesis = text.find("\nthesis = \"");
        ASSERT_NE(thesis, std::string::npos) << "the template has no thesis key";
        text = text.substr(0, thesis) + "\nthesis = " + toml_string(payload) + text.substr(text.find('\n', thesis + 1));
      }
      support::write_file(file, text);
      const auto r = demwb({"run", file.string(), "--engine", "lammps,yade,liggghts", "--no-cache", "--no-time-step-check", "-o",
                            out.string()});
      EXPECT_FALSE(fs::exists(sentinel)) << label << ": a payload ran a command";
      fs::remove(sentinel);
      if (r.exit_code == 2) {  // refused at load time: the message names the file and the key
        ++refused;
        EXPECT_NE(r.err.find(file.filename().string()), std::string::npos) << label << ": " << r.err;
        const std::string leaf = site.key.substr(site.key.rfind('.') + 1);
        EXPECT_TRUE(r.err.find(leaf) != std::string::npos || site.key == "materials.<name>") << label << ": " << r.err;
        EXPECT_EQ(r.err.find("\nshell"), std::string::npos) << label << ": the message echoes a raw newline";
        continue;
      }
      ++ran;
      // Accepted: the runs are exactly the untouched case's.
      EXPECT_EQ(support::read_file(out / "trace_lammps.csv"), lammps_trace) << label;
      EXPECT_EQ(support::read_file(out / "trace_yade.csv"), yade_trace) << label;
      EXPECT_EQ(support::read_file(out / "trace_liggghts.csv"), liggghts_trace) << label;
      const std::string deck = files_named(out, "deck.in");
      EXPECT_FALSE(deck.empty()) << label;
      EXPECT_FALSE(std::regex_search(deck, std::regex("(^|\n)\\s*shell"))) << label << "\n" << deck;
      const std::string report = support::read_file(out / "report.md");
      EXPECT_EQ(report.find("<script>"), std::string::npos) << label;
      // A link needs an unescaped "](": the escaped text "\](" shows as the characters.
      EXPECT_FALSE(std::regex_search(report, std::regex(R"((^|[^\\])\]\(javascript:)"))) << label;
      if (payload.find("javascript:") != std::string::npos) {
        EXPECT_NE(report.find("\\](javascript:"), std::string::npos) << label << ": the payload should show, escaped";
      }
      EXPECT_EQ(report.find("\n# heading"), std::string::npos) << label;
      EXPECT_EQ(report.find('\x1b'), std::string::npos) << label;
    }
  }
  // Free text (description and thesis) is accepted with every payload; every name and keyword refuses.
  EXPECT_EQ(ran, static_cast<int>(payloads("").size()));
  EXPECT_EQ(refused, n - ran);
}

}  // namespace
