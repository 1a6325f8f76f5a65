#pragma once
// "Did you mean ...?": whether an unknown name is probably a slip for a known one.

#include <string_view>

namespace fosssim {

/// True when `unknown` is probably a misspelling of `known`: within two edits (insertions,
/// deletions, substitutions, swaps of neighbours) of it, one for names of three or four letters;
/// names of two letters or fewer are never matched ("px" is not "vx"). Case counts ("SIMPLE" is
/// six edits from "simple").
bool looks_like_misspelling(std::string_view unknown, std::string_view known);

}  // namespace fosssim
