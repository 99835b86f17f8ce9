// support/text.hpp's printable and support/text_file.hpp: what a user's file or name may
// hold, and the one-line reasons a file is refused (issue 17's bad-input list).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "support/text.hpp"
#include "support/text_file.hpp"

namespace {

std::string refusal(const std::string& path, std::size_t max_bytes = 1 << 20) {
  try {
    support::read_text_file(path, max_bytes);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::filesystem::path written(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

} // namespace

TEST_CASE("printable: control bytes and broken UTF-8 escaped, UTF-8 kept", "[support]") {
  CHECK(support::printable("plain") == "plain");
  CHECK(support::printable(std::string("a\0b", 3)) == "a\\x00b");
  CHECK(support::printable("tab\tend\x7f") == "tab\\x09end\\x7f");
  CHECK(support::printable("données ≤ ε") == "données ≤ ε");
  CHECK(support::printable("bad \xff\xfe lead") == "bad \\xff\\xfe lead");
  CHECK(support::printable("cut \xc3") == "cut \\xc3");  // a sequence cut short
  CHECK(support::printable("\xc3(") == "\\xc3(");        // a lead without continuation
  CHECK(support::printable("\xc0\xaf") == "\\xc0\\xaf"); // overlong: not valid UTF-8
}

TEST_CASE("read_text_file: the text, or one reason", "[support]") {
  CHECK(support::read_text_file(written("tioa_text_ok.txt", "a\nb\n").string(), 100) == "a\nb\n");
  CHECK(refusal("") == "an empty file name");
  CHECK_THAT(refusal("/no/such/file"), Catch::EndsWith("No such file or directory"));
  CHECK_THAT(refusal(std::filesystem::temp_directory_path().string()),
             Catch::EndsWith(": is a directory, not a file"));
  CHECK(refusal("/dev/zero") == "/dev/zero: not a regular file");
  CHECK_THAT(refusal(written("tioa_text_big.txt", std::string(101, 'x')).string(), 100),
             Catch::EndsWith(": 101 bytes, larger than 100: not one of ours"));
  CHECK_THAT(refusal(written("tioa_text_nul.txt", std::string("ab\0c", 4)).string()),
             Catch::EndsWith(": holds a NUL byte at offset 2: not a text file"));
}

TEST_CASE("read_text_stream: a bounded read of standard input", "[support]") {
  std::istringstream small("x y\n");
  CHECK(support::read_text_stream(small, "-", 10) == "x y\n");
  std::istringstream big(std::string(11, 'x'));
  CHECK_THROWS_WITH(support::read_text_stream(big, "-", 10),
                    "-: larger than 10 bytes: not one of ours");
}
