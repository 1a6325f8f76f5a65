#include "core/misspelling.h"

#include <algorithm>
#include <vector>

namespace fosssim {

namespace {

/// The optimal-string-alignment distance (insertions, deletions, substitutions and swaps of
/// neighbours), stopping early: returns `cap` + 1 for anything farther than `cap`. Attribute
/// names are short, so the quadratic table is small.
int edit_distance(std::string_view a, std::string_view b, int cap) {
  const int n = static_cast<int>(a.size());
  const int m = static_cast<int>(b.size());
  if (n - m > cap || m - n > cap || n > 64 || m > 64) return cap + 1;
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (int i = 0; i <= n; ++i) d[i][0] = i;
  for (int j = 0; j <= m; ++j) d[0][j] = j;
  for (int i = 1; i <= n; ++i) {
    for (int j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      int best = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        best = std::min(best, d[i - 2][j - 2] + 1);
      }
      d[i][j] = best;
    }
  }
  return std::min(d[n][m], cap + 1);
}

}  // namespace

/// Two edits catch the usual slips ("alhpa", "poisonratio", "raduis") without pairing
/// unrelated short names.
bool looks_like_misspelling(std::string_view unknown, std::string_view known) {
  constexpr int kMisspellingEdits = 2;
  if (known.size() <= 2 || unknown == known) return false;
  const int cap = known.size() <= 4 ? 1 : kMisspellingEdits;
  return edit_distance(unknown, known, cap) <= cap;
}

}  // namespace fosssim
