#pragma once
// Second-order forward-mode automatic differentiation on N local variables.
// The reference rod writes each element energy once, as a function of its
// local unknowns; value, gradient and Hessian then follow exactly (no finite
// differences, no hand-derived second derivatives to get wrong). N is 6 for
// every element of the rod (two frame increments, or one edge vector and one
// frame increment), so the N x N Hessian carried through each operation is
// cheap enough.
#include <Eigen/Core>
#include <cmath>

namespace refrod {

template <int N>
struct Jet {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  double v = 0;
  Vec g = Vec::Zero();
  Mat H = Mat::Zero();

  Jet() = default;
  Jet(double c) : v(c) {}  // NOLINT: constants mix freely with jets
  // The i-th independent variable at value c.
  static Jet variable(int i, double c) {
    Jet j(c);
    j.g[i] = 1;
    return j;
  }
};

template <int N> Jet<N> operator+(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v + b.v, r.g = a.g + b.g, r.H = a.H + b.H;
  return r;
}
template <int N> Jet<N> operator-(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v - b.v, r.g = a.g - b.g, r.H = a.H - b.H;
  return r;
}
template <int N> Jet<N> operator-(const Jet<N>& a) {
  Jet<N> r;
  r.v = -a.v, r.g = -a.g, r.H = -a.H;
  return r;
}
template <int N> Jet<N> operator*(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  r.H = a.v * b.H + b.v * a.H + a.g * b.g.transpose() + b.g * a.g.transpose();
  return r;
}
template <int N> Jet<N> operator*(double c, const Jet<N>& a) {
  Jet<N> r;
  r.v = c * a.v, r.g = c * a.g, r.H = c * a.H;
  return r;
}
template <int N> Jet<N> operator*(const Jet<N>& a, double c) { return c * a; }
template <int N> Jet<N> operator+(const Jet<N>& a, double c) {
  Jet<N> r = a;
  r.v += c;
  return r;
}
template <int N> Jet<N> operator+(double c, const Jet<N>& a) { return a + c; }
template <int N> Jet<N> operator-(const Jet<N>& a, double c) { return a + (-c); }

// f(a) by the chain rule: f' a.g, f' a.H + f'' a.g a.g^T.
template <int N> Jet<N> chain(const Jet<N>& a, double f, double df, double ddf) {
  Jet<N> r;
  r.v = f;
  r.g = df * a.g;
  r.H = df * a.H + ddf * a.g * a.g.transpose();
  return r;
}
// 1/sqrt(a); a > 0 is the caller's business (1 + |w|^2/4 here, never small).
template <int N> Jet<N> rsqrt(const Jet<N>& a) {
  const double s = 1.0 / std::sqrt(a.v);
  return chain(a, s, -0.5 * s / a.v, 0.75 * s / (a.v * a.v));
}
template <int N> Jet<N> inverse(const Jet<N>& a) {
  const double i = 1.0 / a.v;
  return chain(a, i, -i * i, 2 * i * i * i);
}

}  // namespace refrod
