// Hostile text in a Markdown page: a '|', a line break or HTML in a name, title or reason
// cannot break a table or inject markup.
#include "report/markdown_text.hpp"

#include <gtest/gtest.h>

namespace bb {
namespace {

TEST(MarkdownText, PlainTextIsUnchanged) {
  EXPECT_EQ(markdown_text("course/rk4 diverged at 1.2 s (ball_1.x())"),
            "course/rk4 diverged at 1.2 s (ball_1.x())");
  EXPECT_EQ(markdown_text(""), "");
}

TEST(MarkdownText, PipesAreEscaped) {
  EXPECT_EQ(markdown_text("a|b||c"), "a\\|b\\|\\|c");
}

TEST(MarkdownText, ABackslashCannotUnescapeTheNextPipe) {
  EXPECT_EQ(markdown_text("a\\|b"), "a\\\\\\|b");
  EXPECT_EQ(markdown_text("end\\"), "end\\\\");
}

TEST(MarkdownText, DollarsStartNoMath) {
  EXPECT_EQ(markdown_text("set $\\epsilon$ to 0"), "set \\$\\\\epsilon\\$ to 0");
}

TEST(MarkdownText, EachLineBreakBecomesOneSpace) {
  EXPECT_EQ(markdown_text("one\ntwo\r\nthree\rfour\n\n"), "one two three four  ");
}

TEST(MarkdownText, HtmlBecomesEntities) {
  EXPECT_EQ(markdown_text("<script>alert('x')</script>"),
            "&lt;script&gt;alert('x')&lt;/script&gt;");
  // An entity in the text is shown as written, not decoded.
  EXPECT_EQ(markdown_text("&lt; & <"), "&amp;lt; &amp; &lt;");
}

}  // namespace
}  // namespace bb
