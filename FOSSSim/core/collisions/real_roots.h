#pragma once
// The real roots of a polynomial, found robustly without a library.

#include <vector>

namespace fosssim {

/// The real roots of the polynomial with these coefficients (highest degree first, the first
/// nonzero), in increasing order; a root of multiplicity m > 1 may appear up to m times.
///
/// Method: exact zero coefficients at the tail are roots at exactly 0 and are divided out. The
/// real line is then cut at the real roots of the derivative (found the same way, recursively)
/// and at a bound on the roots' size (Cauchy's, 1 + max |a_k/a_n|), so that the polynomial is
/// monotone between consecutive cuts; each piece whose ends differ in sign holds one root,
/// found by Newton's method safeguarded by bisection to full double precision. A cut where the
/// polynomial touches zero within the round-off of its evaluation (a double root) counts as a
/// root. Real roots of a polynomial of degree n are found to an error of about the condition of
/// the root times the unit round-off; clusters of roots shrink to where evaluation round-off
/// hides them, as with any method in double precision.
std::vector<double> real_roots(const std::vector<double>& highest_first);

}  // namespace fosssim
