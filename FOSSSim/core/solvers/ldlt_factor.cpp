#include "core/solvers/ldlt_factor.h"

#include <dmumps_c.h>
#include <smumps_c.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/solvers/solver_failure.h"
#include "core/solvers/solver_libraries.h"

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

/// The MUMPS library of one arithmetic: its instance structure, its real type and its entry
/// point (MUMPS builds one library per arithmetic, from the same sources), loaded on demand
/// (core/solvers/solver_libraries.h).
template <class Struct, class Real, auto kEntry>
struct MumpsArithmetic {
  using Instance = Struct;
  using Scalar = Real;
  static void call(Struct* id) { (mumps_library().*kEntry)(id); }
};
using DoubleMumps = MumpsArithmetic<DMUMPS_STRUC_C, double, &MumpsLibrary::dmumps_c>;
using SingleMumps = MumpsArithmetic<SMUMPS_STRUC_C, float, &MumpsLibrary::smumps_c>;

/// MUMPS's instance, in either arithmetic: its control and information arrays, the values it
/// factors and the factor it holds.
struct LdltFactor::Mumps {
  virtual ~Mumps() = default;
  /// Points MUMPS at the pattern (1-based rows and columns, kept by the caller) and analyses it.
  virtual void analyze(int n, std::vector<int>& rows, std::vector<int>& columns) = 0;
  /// Takes the values to factor, value[slots[e]] for the e-th analysed entry; false when one
  /// does not fit the arithmetic (beyond float's range, for a single-precision factor).
  virtual bool set_values(const double* value, const std::vector<int>& slots) = 0;
  /// Runs MUMPS's phase `job` (1 analysis, 2 factorization, 3 solve, -1 start, -2 end).
  virtual void run(int job) = 0;
  /// x = A⁻¹ b with the factor.
  virtual void solve(const double* b, double* x) = 0;
  /// MUMPS's ICNTL(k), INFOG(k) and RINFOG(k), numbered from 1 as in its documentation.
  virtual int& control(int k) = 0;
  virtual int info(int k) const = 0;
  virtual double real_info(int k) const = 0;
};

namespace {

template <class Arithmetic>
class MumpsOf final : public LdltFactor::Mumps {
  using Real = typename Arithmetic::Scalar;

 public:
  MumpsOf() {
    id_.comm_fortran = kUseCommWorld;
    id_.par = 1;  // this process takes part in the work
    id_.sym = 2;  // general symmetric: L D Lᵀ with 1×1 and 2×2 pivots
    run(-1);
    if (id_.infog[0] < 0) throw SolverFailure("MUMPS: could not start");
    // Never print: failures are reported through return values.
    control(1) = -1;
    control(2) = -1;
    control(3) = -1;
    control(4) = 0;
    control(7) = kOrderingPord;
  }
  ~MumpsOf() override { run(-2); }
  MumpsOf(const MumpsOf&) = delete;
  MumpsOf& operator=(const MumpsOf&) = delete;

  void analyze(int n, std::vector<int>& rows, std::vector<int>& columns) override {
    // MUMPS keeps the pointers; the caller keeps the arrays alive and unchanged.
    values_.assign(rows.size(), Real{0});
    rhs_.assign(static_cast<std::size_t>(n), Real{0});
    id_.n = n;
    id_.nnz = static_cast<MUMPS_INT8>(rows.size());
    id_.irn = rows.data();
    id_.jcn = columns.data();
    id_.a = values_.data();
    run(1);
  }

  bool set_values(const double* value, const std::vector<int>& slots) override {
    for (std::size_t e = 0; e < slots.size(); ++e) {
      const double v = value[slots[e]];
      if (!(std::abs(v) <= std::numeric_limits<Real>::max())) return false;
      values_[e] = static_cast<Real>(v);
    }
    return true;
  }

  void solve(const double* b, double* x) override {
    std::copy(b, b + id_.n, rhs_.begin());
    id_.rhs = rhs_.data();
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    run(3);
    std::copy(rhs_.begin(), rhs_.end(), x);
  }

  int& control(int k) override { return id_.icntl[k - 1]; }
  int info(int k) const override { return id_.infog[k - 1]; }
  double real_info(int k) const override { return id_.rinfog[k - 1]; }

  void run(int job) override {
    if (job == 2) provide_workspace();
    id_.job = job;
    Arithmetic::call(&id_);
  }

 private:
  /// Gives MUMPS its main workspace (WK_USER), kept from one factorization to the next: left to
  /// itself, MUMPS allocates it afresh at every factorization, and first touching its pages
  /// was a twentieth of a small 3D step (the CSC417 bunny). The size is the analysis's
  /// estimate, INFO(8) entries (negative: millions), with the relaxation ICNTL(14) in percent
  /// that MUMPS itself would add; factorize's retries raise ICNTL(14), and so the size. Beyond
  /// an int's range MUMPS allocates as before. The same operations either way.
  void provide_workspace() {
    const long long estimate = id_.info[7] >= 0 ? id_.info[7] : -1000000LL * id_.info[7];
    const long long relaxation = std::max(id_.icntl[13], 0);
    const long long wanted = estimate + estimate * relaxation / 100 + 1;
    if (estimate <= 0 || wanted > std::numeric_limits<MUMPS_INT>::max()) {
      id_.wk_user = nullptr;
      id_.lwk_user = 0;
      return;
    }
    if (workspace_size_ < wanted) {
      workspace_.reset();  // the old factor is not needed: no two copies at once
      // Not zeroed: pages MUMPS never touches (the relaxation's) stay unmapped, as with its own.
      workspace_.reset(new Real[static_cast<std::size_t>(wanted)]);
      workspace_size_ = wanted;
    }
    id_.wk_user = workspace_.get();
    id_.lwk_user = static_cast<MUMPS_INT>(workspace_size_);
  }

  typename Arithmetic::Instance id_{};
  std::vector<Real> values_;  // the lower triangle's values, in MUMPS's arithmetic
  std::vector<Real> rhs_;     // MUMPS solves in place
  std::unique_ptr<Real[]> workspace_;  // WK_USER: the factorization's workspace and factor
  long long workspace_size_ = 0;       // its entries
};

std::unique_ptr<LdltFactor::Mumps> start_mumps(FactorPrecision precision) {
  if (precision == FactorPrecision::kSingle) return std::make_unique<MumpsOf<SingleMumps>>();
  return std::make_unique<MumpsOf<DoubleMumps>>();
}

}  // namespace

LdltFactor::LdltFactor(FactorPrecision precision)
    : precision_(precision), mumps_(start_mumps(precision)) {}

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
  mumps_->analyze(size_, rows_, columns_);
  if (mumps_->info(1) < 0) {
    throw SolverFailure(
        "MUMPS: the analysis failed (INFOG(1) = " + std::to_string(mumps_->info(1)) + ")");
  }
  analysed_ = true;
}

bool LdltFactor::factorize(const SparseMatrix& A) {
  if (!analysed_ || A.rows() != size_) {
    throw std::logic_error("LdltFactor::factorize: the pattern was not analysed");
  }
  factored_ = false;
  if (!mumps_->set_values(A.valuePtr(), slots_)) return false;
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
  mumps_->solve(b, x);
  if (mumps_->info(1) < 0) throw SolverFailure("MUMPS: the solve failed");
}

}  // namespace fosssim
