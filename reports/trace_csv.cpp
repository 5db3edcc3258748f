// SPDX-License-Identifier: MIT
#include "reports/trace_csv.hpp"

#include <fmt/format.h>

namespace reports {

std::string trace_csv(const cases::Trace& trace) {
  std::string out;
  const auto& names = trace.columns();
  for (std::size_t c = 0; c < names.size(); ++c) out += (c == 0 ? "" : ",") + names[c];
  out += "\n";
  for (std::size_t r = 0; r < trace.rows(); ++r) {
    for (std::size_t c = 0; c < names.size(); ++c) {
      if (c != 0) out += ',';
      out += fmt::format("{:.17g}", trace.values(c)[r]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace reports
