// A Form that is a sum over elements of `Arity` particles each (a tet, a spring, a particle).
// Subclasses give one element's value, gradient and Hessian in its 3·Arity local
// coordinates; this class gathers, sums and scatters. Work runs in parallel over fixed
// chunks of elements and is combined in chunk order, so results do not depend on the
// number of threads.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

#include "fem_reference/form.hpp"
#include "fem_reference/psd_projection.hpp"
#include "fem_reference/sparse_hessian.hpp"

namespace rice::fem {

template <int Arity>
class ElementForm : public Form {
 public:
  static constexpr int kSize = 3 * Arity;
  using LocalVector = Eigen::Matrix<double, kSize, 1>;
  using LocalMatrix = Eigen::Matrix<double, kSize, kSize>;
  using Particles = std::array<int, Arity>;

  double value(const Positions& x) const override {
    std::vector<double> sums(chunk_count());
    for_each_chunk([&](int chunk, int begin, int end) {
      double sum = 0.0;
      for (int e = begin; e < end; ++e) sum += element_value(e, gather(x, e));
      sums[chunk] = sum;
    });
    double total = 0.0;
    for (double s : sums) total += s;
    return total;
  }

  void add_gradient(const Positions& x, double weight, Positions& gradient) const override {
    std::vector<LocalVector> local(std::min(kChunk, element_count()));
    for (int begin = 0; begin < element_count(); begin += kChunk) {  // bounded buffer
      const int end = std::min(begin + kChunk, element_count());
      tbb::parallel_for(begin, end, [&](int e) { local[e - begin] = element_gradient(e, gather(x, e)); });
      for (int e = begin; e < end; ++e) {
        const Particles p = element_particles(e);
        for (int a = 0; a < Arity; ++a)
          gradient.row(p[a]) += weight * local[e - begin].template segment<3>(3 * a).transpose();
      }
    }
  }

  void add_hessian(const Positions& x, double weight, bool project,
                   SparseHessian& hessian) const override {
    std::vector<LocalMatrix> local(std::min(kChunk, element_count()));
    for (int begin = 0; begin < element_count(); begin += kChunk) {
      const int end = std::min(begin + kChunk, element_count());
      tbb::parallel_for(begin, end, [&](int e) {
        local[e - begin] = element_hessian(e, gather(x, e), project);
      });
      for (int e = begin; e < end; ++e) {
        const Particles p = element_particles(e);
        hessian.add<kSize>(p.data(), local[e - begin], weight);
      }
    }
  }

  Stencils stencils() const override {
    Stencils s{Arity, {}};
    s.particles.reserve(static_cast<size_t>(Arity) * element_count());
    for (int e = 0; e < element_count(); ++e) {
      const Particles p = element_particles(e);
      s.particles.insert(s.particles.end(), p.begin(), p.end());
    }
    return s;
  }

  virtual int element_count() const = 0;
  virtual Particles element_particles(int e) const = 0;
  virtual double element_value(int e, const LocalVector& x) const = 0;
  virtual LocalVector element_gradient(int e, const LocalVector& x) const = 0;
  /// With `project`, the result must be positive semi-definite.
  virtual LocalMatrix element_hessian(int e, const LocalVector& x, bool project) const = 0;

  LocalVector gather(const Positions& x, int e) const {
    const Particles p = element_particles(e);
    LocalVector local;
    for (int a = 0; a < Arity; ++a) local.template segment<3>(3 * a) = x.row(p[a]).transpose();
    return local;
  }

 private:
  static constexpr int kChunk = 4096;
  int chunk_count() const { return (element_count() + kChunk - 1) / kChunk; }

  template <class Work>
  void for_each_chunk(Work&& work) const {
    tbb::parallel_for(0, chunk_count(), [&](int chunk) {
      work(chunk, chunk * kChunk, std::min((chunk + 1) * kChunk, element_count()));
    });
  }
};

}  // namespace rice::fem
