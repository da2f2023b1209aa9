#pragma once
// The command line's number parsing, shared by RunOptions.cpp and AccuracyOptions.cpp: one rule for what a
// number is and one wording for the errors.

#include <string>

namespace physim {

/// The whole of `text` as a finite number; throws UsageError naming `flag` and the text otherwise.
double parseNumberOption(const std::string& flag, const std::string& text);
/// A whole number in [lo, hi] (written as an integer or as a number equal to one, e.g. 8 or 8.0); throws
/// UsageError naming `flag`, the bounds and the text otherwise.
int parseCountOption(const std::string& flag, const std::string& text, int lo, int hi);

}  // namespace physim
