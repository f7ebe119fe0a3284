// Small text-scanning helpers shared by the PLY header, OBJ and OFF readers.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace qd::io {

bool is_space(char c);

// Splits off the next line at `pos` (without its "\n" or "\r\n"); false at the end of `bytes`.
bool next_line(std::string_view bytes, std::size_t& pos, std::string_view& line);

// Words of a line separated by blanks (spaces, tabs, carriage returns).
std::vector<std::string_view> split_words(std::string_view line);

// Parses a whole token as a number (an optional leading '+' is allowed); false if it is not one.
bool parse_number(std::string_view token, double& value);

// Parses a whole token as a decimal integer (optional sign); false if it is not one.
bool parse_integer(std::string_view token, long long& value);

}  // namespace qd::io
