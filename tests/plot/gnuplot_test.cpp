// Running gnuplot itself: quoting arbitrary text, and reporting what gnuplot said when a
// script fails.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "plot/Gnuplot.h"
#include "core/ScratchDirectory.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

TEST(Gnuplot, StringLiteralsDoubleSingleQuotesAndFlattenLineBreaks) {
  EXPECT_EQ(gnuplot_string("plain"), "'plain'");
  EXPECT_EQ(gnuplot_string("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_string("a\"b\\n@c_d"), "'a\"b\\n@c_d'");
  EXPECT_EQ(gnuplot_string("two\nlines\r\t"), "'two lines  '");
}

TEST(Gnuplot, QuotedTextReachesTheOutputVerbatim) {
  auto dir = ScratchDirectory::create("plot");
  ASSERT_TRUE(dir) << dir.error().to_string();
  const std::string tricky = R"(it's "q" a_b^c {x} \n @GPVAL_TERM $0 #no comment)";
  const fs::path script = dir->path() / "t.gp", table = dir->path() / "out.txt";
  std::ofstream(script) << "set print " << gnuplot_string(table.string()) << "\nprint " << gnuplot_string(tricky) << "\n";
  auto ran = run_gnuplot("gnuplot", script);
  ASSERT_TRUE(ran) << ran.error().to_string();
  std::ifstream in(table);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, tricky);
}

TEST(Gnuplot, AFailingScriptReportsGnuplotsErrorLine) {
  auto dir = ScratchDirectory::create("plot");
  ASSERT_TRUE(dir) << dir.error().to_string();
  const fs::path script = dir->path() / "bad.gp";
  std::ofstream(script) << "set terminal dumb\nset output '/dev/null'\nplot no_such_variable_here\n";
  auto ran = run_gnuplot("gnuplot", script);
  ASSERT_FALSE(ran);
  EXPECT_EQ(ran.error().stage, ErrorStage::plot);
  EXPECT_NE(ran.error().message.find("gnuplot failed (exit 1)"), std::string::npos) << ran.error().message;
  EXPECT_NE(ran.error().message.find("no_such_variable_here"), std::string::npos) << ran.error().message;
}

TEST(Gnuplot, ScratchDirectoryIsRemovedWithItsContents) {
  fs::path kept;
  {
    auto dir = ScratchDirectory::create("plot");
    ASSERT_TRUE(dir) << dir.error().to_string();
    kept = dir->path();
    std::ofstream(kept / "file") << "x";
    EXPECT_TRUE(fs::exists(kept / "file"));
  }
  EXPECT_FALSE(fs::exists(kept));
}

}  // namespace
}  // namespace shaderbed
