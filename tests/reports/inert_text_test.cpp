// SPDX-License-Identifier: MIT
// Free text from a case file reaches report.md inert: no HTML, link, image, code or heading.
#include <string>

#include <gtest/gtest.h>

#include "reports/markdown.hpp"

namespace inert_text_test {

TEST(InertText, HtmlLinksImagesCodeAndLineBreaksAreDisarmed) {
  const std::string payload =
      "<script>alert(1)</script> [x](javascript:alert(1)) ![i](http://e/x.png) `rm -rf` # h\n# "
      "heading\r| a | b | **bold** & \\";
  const std::string out = reports::inert_text(payload);
  EXPECT_EQ(out.find('<'), std::string::npos);
  EXPECT_EQ(out.find('>'), std::string::npos);
  EXPECT_EQ(out.find('\n'), std::string::npos);
  EXPECT_EQ(out.find('\r'), std::string::npos);
  EXPECT_NE(out.find("&lt;script&gt;"), std::string::npos);
  EXPECT_NE(out.find("\\[x\\](javascript:alert(1))"), std::string::npos);
  EXPECT_NE(out.find("\\!\\[i\\]"), std::string::npos);
  EXPECT_NE(out.find("\\`rm -rf\\`"), std::string::npos);
  EXPECT_NE(out.find("\\# heading"), std::string::npos);
  EXPECT_NE(out.find("\\| a \\| b \\|"), std::string::npos);
  EXPECT_NE(out.find("\\*\\*bold\\*\\* &amp; \\\\"), std::string::npos);
}

TEST(InertText, OrdinaryDescriptionsReadAsWritten) {
  EXPECT_EQ(reports::inert_text("125-sphere agglomerate (k_e 1e5, λ 1.5) hits a wall at 3 m/s, 45°."),
            "125-sphere agglomerate (k_e 1e5, λ 1.5) hits a wall at 3 m/s, 45°.");
}

}  // namespace
