// docs/design.md's "Command line" names every option each subcommand takes: each `--option`
// the program's --help lists for a subcommand (a line of its own) is in that subcommand's
// lines of the usage block (a new option, such as --trajectory, is documented where users look for
// it).
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The `--options` in `text`: each word that starts with "--", up to a character that
/// cannot be in an option's name.
std::set<std::string> options_in(const std::string& text) {
  std::set<std::string> out;
  for (std::size_t at = 0; (at = text.find("--", at)) != std::string::npos;) {
    std::size_t end = at + 2;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-'))
      ++end;
    if (end > at + 2 && (at == 0 || text[at - 1] == ' ' || text[at - 1] == '['))
      out.insert(text.substr(at, end - at));
    at = end;
  }
  return out;
}

/// The options a --help lists: each line that starts (after its indent) with "--".
std::set<std::string> listed_options(const std::string& help) {
  std::set<std::string> out;
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find_first_not_of(' ');
    if (at != std::string::npos && line.compare(at, 2, "--") == 0)
      out.insert(line.substr(at, line.find(' ', at) - at));
  }
  return out;
}

/// The lines of the usage block of docs/design.md that belong to `command` ("beachball
/// <command>" and the lines under it up to the next command).
std::string usage_of(const std::string& command) {
  const std::string doc = test::bytes(test::source_path("docs/design.md"));
  const std::size_t block = doc.find("## Command line");
  const std::size_t start = doc.find("beachball " + command + " ", block);
  if (block == std::string::npos || start == std::string::npos) return "";
  const std::size_t next = doc.find("\nbeachball ", start + 1);
  const std::size_t end = std::min(next, doc.find("```", start));
  return doc.substr(start, end - start);
}

TEST(CommandLineDoc, EveryOptionOfEverySubcommandIsInItsUsage) {
  for (const std::string command : {"list", "run", "report", "merge", "check", "stability"}) {
    SCOPED_TRACE(command);
    const test::Outcome help = test::beachball(command + " --help");
    ASSERT_EQ(help.exit_code, 0) << help.out;
    const std::string usage = usage_of(command);
    ASSERT_FALSE(usage.empty());
    const std::set<std::string> documented = options_in(usage);
    for (const std::string& option : listed_options(help.out))
      if (option != "--help") {
        EXPECT_TRUE(documented.count(option)) << option << "\n" << usage;
      }
  }
}

}  // namespace
}  // namespace bb
