// Pieces of the messages written for the user: numbers as text and counted nouns.
#pragma once

#include <string>

namespace qd::common {

std::string to_text(int n);
// As an ostream writes it by default (6 significant digits).
std::string to_text(double x);
// "1 face", "3 faces".
std::string count_text(int n, const char* one, const char* many);

}  // namespace qd::common
