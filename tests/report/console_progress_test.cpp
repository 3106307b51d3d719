// Progress on stderr: one refreshed line on a terminal, a plain line per tenth of the cells
// elsewhere (not one per cell), nothing off a terminal with --quiet.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "report/ConsoleProgress.h"

namespace shaderbed {
namespace {

// Feeds `total` cells, the ones in `failing` not passing; returns what was printed.
std::string progress(size_t total, bool terminal, bool quiet, size_t failing = 0) {
  std::FILE* out = std::tmpfile();
  ConsoleProgress p(out, terminal, quiet);
  for (size_t done = 1; done <= total; ++done)
    p.update(done, total, CellResult{.status = done <= failing ? CellStatus::fail : CellStatus::pass});
  std::string s(size_t(std::ftell(out)), '\0');
  std::rewind(out);
  s.resize(std::fread(s.data(), 1, s.size(), out));
  std::fclose(out);
  return s;
}

size_t occurrences(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

TEST(ConsoleProgress, PlainLinesAtEveryTenth) {
  const std::string log = progress(1400, false, false, 3);
  EXPECT_EQ(occurrences(log, "\n"), 10u) << log;
  EXPECT_EQ(log.find('\r'), std::string::npos);
  EXPECT_TRUE(log.starts_with("progress: 140/1400 cells (10%), ")) << log;
  EXPECT_NE(log.find("progress: 1400/1400 cells (100%), "), std::string::npos) << log;
  EXPECT_NE(log.find("3 not passing\n"), std::string::npos) << log;
  // A small run does not print more lines than cells, nor a line per cell of a large one.
  EXPECT_EQ(occurrences(progress(3, false, false), "\n"), 3u);
  EXPECT_EQ(occurrences(progress(7, false, false), "\n"), 7u);
  EXPECT_EQ(occurrences(progress(23, false, false), "\n"), 10u);
  EXPECT_EQ(progress(1400, false, true), "") << "--quiet off a terminal";
}

TEST(ConsoleProgress, OneRefreshedLineOnATerminal) {
  const std::string tty = progress(500, true, false, 1);
  EXPECT_EQ(tty.find('\n'), std::string::npos) << "refreshed in place, never scrolled";
  EXPECT_TRUE(tty.starts_with("\r[   1/500]")) << tty;
  EXPECT_NE(tty.find("[ 500/500]"), std::string::npos) << "the last cell is always drawn";
  EXPECT_NE(tty.find("ETA"), std::string::npos);
  EXPECT_NE(tty.find("1 not passing"), std::string::npos);
  EXPECT_TRUE(tty.ends_with("\r\x1b[K")) << "and erased at the end";
  EXPECT_LT(occurrences(tty, "\r["), 50u) << "redraws are throttled";
}

}  // namespace
}  // namespace shaderbed
