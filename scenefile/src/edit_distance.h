// "Did you mean ...?" for misspelt keys and names.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace particles::scenefile {

// Edits (insert, delete, substitute, swap two neighbours) turning a into b.
int editDistance(std::string_view a, std::string_view b);

// The first of `known` within 2 edits of `word`, closest first; "" if none.
std::string closestMatch(std::string_view word, std::span<const std::string_view> known);

}  // namespace particles::scenefile
