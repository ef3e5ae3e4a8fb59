#pragma once
/// \file
/// "Did you mean …?" for misspelt keys, sections and subcommands.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace newtop::io {

/// Edit distance between a and b: insertions, deletions, substitutions and transpositions of
/// adjacent characters each count 1 (optimal string alignment); letters differing only in case
/// count as equal.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is close enough to be a misspelling of it (edit
/// distance at most 1 for names of up to 4 characters, 2 up to 8, 3 beyond; a word of one or two
/// characters only by case); the first of equally close candidates. std::nullopt otherwise.
std::optional<std::string> closest_name(std::string_view word,
                                        const std::vector<std::string>& candidates);

}  // namespace newtop::io
