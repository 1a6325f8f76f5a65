#include "core/solvers/ldlt_factor.h"

#include <dmumps_c.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fosssim {

namespace {
/// MUMPS's name for "the whole (here: the only) process" in its Fortran interface.
constexpr int kUseCommWorld = -987654;
/// The fill-reducing ordering MUMPS computes once per pattern: PORD, which gave the fewest
/// factorization flops on FOSSSim's cloth meshes (81×81 cloth: 0.99 GFlop; AMF 1.11, METIS
/// 1.47, AMD 1.47; measured with bench_implicit's scenes).
constexpr int kOrderingPord = 4;
/// How often a factorization that ran out of its estimated workspace (delayed pivots) is
/// retried with more, doubling the extra room each time.
constexpr int kWorkspaceRetries = 4;
}  // namespace

/// MUMPS's instance: its control and information arrays and the factor it holds.
struct LdltFactor::Mumps {
  DMUMPS_STRUC_C id{};

  Mumps() {
    id.comm_fortran = kUseCommWorld;
    id.par = 1;  // this process takes part in the work
    id.sym = 2;  // general symmetric: L D Lᵀ with 1×1 and 2×2 pivots
    id.job = -1;
    dmumps_c(&id);
    if (id.infog[0] < 0) throw std::runtime_error("MUMPS: could not start");
    // Never print: failures are reported through return values.
    control(1) = -1;
    control(2) = -1;
    control(3) = -1;
    control(4) = 0;
    control(7) = kOrderingPord;
  }
  ~Mumps() {
    id.job = -2;
    dmumps_c(&id);
  }
  Mumps(const Mumps&) = delete;
  Mumps& operator=(const Mumps&) = delete;

  /// MUMPS's ICNTL(k), numbered from 1 as in its documentation.
  int& control(int k) { return id.icntl[k - 1]; }
  /// MUMPS's INFOG(k).
  int info(int k) const { return id.infog[k - 1]; }
  /// MUMPS's RINFOG(k).
  double real_info(int k) const { return id.rinfog[k - 1]; }
  void run(int job) {
    id.job = job;
    dmumps_c(&id);
  }
};

LdltFactor::LdltFactor() : mumps_(std::make_unique<Mumps>()) {}

LdltFactor::~LdltFactor() = default;

void LdltFactor::analyze(const SparseMatrix& A) {
  if (A.rows() != A.cols()) throw std::logic_error("LdltFactor: the matrix is not square");
  factored_ = false;
  analysed_ = false;
  size_ = static_cast<int>(A.rows());
  rows_.clear();
  columns_.clear();
  slots_.clear();
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  for (int j = 0; j < size_; ++j) {
    for (auto k = outer[j]; k < outer[j + 1]; ++k) {
      if (inner[k] < j) continue;  // the upper triangle is A's lower one, transposed
      rows_.push_back(inner[k] + 1);
      columns_.push_back(j + 1);
      slots_.push_back(static_cast<int>(k));
    }
  }
  values_.assign(slots_.size(), 0.0);
  rhs_.assign(static_cast<std::size_t>(size_), 0.0);
  DMUMPS_STRUC_C& id = mumps_->id;
  id.n = size_;
  id.nnz = static_cast<MUMPS_INT8>(rows_.size());
  id.irn = rows_.data();
  id.jcn = columns_.data();
  id.a = values_.data();
  mumps_->run(1);
  if (mumps_->info(1) < 0) {
    throw std::runtime_error(
        "MUMPS: the analysis failed (INFOG(1) = " + std::to_string(mumps_->info(1)) + ")");
  }
  analysed_ = true;
}

bool LdltFactor::factorize(const SparseMatrix& A) {
  if (!analysed_ || A.rows() != size_) {
    throw std::logic_error("LdltFactor::factorize: the pattern was not analysed");
  }
  const double* value = A.valuePtr();
  for (std::size_t e = 0; e < slots_.size(); ++e) values_[e] = value[slots_[e]];
  const int default_room = mumps_->control(14);
  for (int attempt = 0;; ++attempt) {
    mumps_->run(2);
    const int status = mumps_->info(1);
    // -8, -9, -14, -15, -17, -20: an internal array was too small, as happens when pivots
    // are delayed beyond what the analysis estimated; more room is the documented remedy.
    const bool out_of_room = status == -8 || status == -9 || status == -14 || status == -15 ||
                             status == -17 || status == -20;
    if (!out_of_room || attempt == kWorkspaceRetries) break;
    mumps_->control(14) = std::max(2 * mumps_->control(14), 40);
  }
  mumps_->control(14) = default_room;
  factored_ = mumps_->info(1) >= 0;
  factor_flops_ = mumps_->real_info(3);
  // INFOG(29) counts the factor's entries; a negative value is in millions (large factors).
  const int entries = mumps_->info(29);
  factor_nonzeros_ = entries >= 0 ? entries : -1e6 * entries;
  negative_pivots_ = mumps_->info(12);
  return factored_;
}

void LdltFactor::solve(const double* b, double* x) const {
  if (!factored_) throw std::logic_error("LdltFactor::solve without a factor");
  std::copy(b, b + size_, rhs_.begin());
  DMUMPS_STRUC_C& id = mumps_->id;
  id.rhs = rhs_.data();
  id.nrhs = 1;
  id.lrhs = size_;
  mumps_->run(3);
  if (mumps_->info(1) < 0) throw std::runtime_error("MUMPS: the solve failed");
  std::copy(rhs_.begin(), rhs_.end(), x);
}

}  // namespace fosssim
