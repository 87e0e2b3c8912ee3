// Approximate distances from a block of vectors to every codeword, as one small matrix product.
// |x - c|^2 = |x|^2 + (|c|^2 - 2 x.c), and only the bracket, the score, is computed: |x|^2 does
// not change which codeword is nearest. This is how BLAS-based k-means is fast, but it rounds
// differently from a direct sum of squared differences, so the score only shortlists: a caller
// re-measures every codeword whose score is within the row's tolerance of the best one, and gets exactly
// what a brute-force scan gets. Vectors and codewords are centred on the codebook mean first,
// because the rounding error grows with the norms and Lab vectors sit far from the origin.
// Weighted L2, where each vector brings its own weights w, is a product too, of twice the length:
// sum w (x - c)^2 = sum w x^2 + [w, w x] . [c^2, -2 c], so it is shortlisted the same way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "compress/training_set.h"

namespace voltree {

class CodewordScorer {
 public:
  static constexpr int kBlock = 12;  // vectors scored per call
  static constexpr int kPanel = 16;  // codewords per panel of the packed codebook

  enum class Distance { kPlain, kWeighted };

  // `use_simd` = false forces the portable kernel (tests compare the two).
  explicit CodewordScorer(const Codebook& codebook, Distance distance = Distance::kPlain, bool use_simd = true);

  size_t size() const { return size_; }
  // Scores per vector: the codebook padded to whole panels; a pad scores +infinity.
  size_t padded_size() const { return norms2_.size(); }

  // For vectors[0, count) (row-major, count <= kBlock), with their weights (row-major, for
  // Distance::kWeighted, else ignored): scores[r * padded_size() + j] for every codeword j,
  // lowest[r] = the smallest of them, and tolerance[r], a bound on how far a score may be from
  // the exact distance minus a constant of the row, twice over (the best and the true nearest
  // may each be off), including SquaredDistance's own rounding. Arrays of kBlock; rows from
  // count on are left unspecified.
  void Score(const float* vectors, const float* weights, int count, float* scores, float* lowest,
             float* tolerance) const;

  // The codewords whose score in `row` is <= limit, ascending, written to `shortlist` (room for
  // padded_size()); returns how many.
  size_t Shortlist(const float* row, float limit, uint32_t* shortlist) const;

 private:
  bool weighted() const { return product_dimension_ != dimension_; }
  // Fills the kernel's rows (kBlock x product_dimension_) and the tolerances.
  void CentreRows(const float* vectors, const float* weights, int count, float* rows, float* tolerance) const;

  int dimension_ = 0;
  int product_dimension_ = 0;  // dimension_, or 2 dimension_ when weighted
  size_t size_ = 0;
  std::vector<float> mean_;  // the centre: codebook mean
  // Panel-major, [panel][component][kPanel]: c - mean, or [-(c - mean)^2 / 2, c - mean] when
  // weighted, so that the kernel's |c|^2 - 2 x.c is the weighted score.
  std::vector<float> panels_;
  std::vector<float> norms2_;  // |c - mean|^2, or 0 when weighted; +infinity for pads
  float max_norm_ = 0;         // max |c - mean|
  bool avx2_ = false;          // this CPU runs the AVX2 + FMA kernel
};

}  // namespace voltree
