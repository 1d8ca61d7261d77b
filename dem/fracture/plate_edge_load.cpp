#include "dem/fracture/plate_edge_load.hpp"

#include "dem/fracture/floating_plate.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <fmt/format.h>

namespace icedem {

namespace {

using Complex = std::complex<double>;
using boost::math::quadrature::gauss_kronrod;

// One wavenumber k of the plate in units of l (D = rho_w g = 1): its modes exp(-lambda_j x), lambda_j^2 =
// k^2 +- i, with p_j = lambda_j^2 - nu k^2 (the edge's moment condition). For a unit edge load the two
// amplitudes A, B solve p1 A + p2 B = 0 and q1 A + q2 B = 1 (q_j = -lambda_j^3 + (2 - nu) k^2 lambda_j,
// the Kirchhoff shear); written without the cancellation of the nearly equal modes at large k:
//   A + B = (lambda1 + lambda2) / E,   p1 A e^(-lambda1 x) + p2 B e^(-lambda2 x) = p1 p2 x e^(-lambda1 x) g(d x) / E,
//   E = p1 p2 + 2 (1 - nu) k^2 (lambda1 lambda2 + nu k^2),  d = lambda2 - lambda1 = -2i / (lambda1 + lambda2),
//   g(z) = (1 - e^-z) / z.
struct Mode {
  Complex l1, l2, p1, p2, e;
};

Mode mode(double k, double nu) {
  Mode m;
  m.l1 = std::sqrt(Complex(k * k, 1.0));
  m.l2 = std::sqrt(Complex(k * k, -1.0));
  m.p1 = m.l1 * m.l1 - nu * k * k;
  m.p2 = m.l2 * m.l2 - nu * k * k;
  m.e = m.p1 * m.p2 + 2 * (1 - nu) * k * k * (m.l1 * m.l2 + nu * k * k);
  return m;
}

Complex divided(Complex z) {  // (1 - e^-z) / z
  if (std::abs(z) < 1e-4) return 1.0 - z / 2.0 + z * z / 6.0;
  return (1.0 - std::exp(-z)) / z;
}

// the load's spectrum: P spread over |y| < a has the transform sin(k a) / (k a)
double spectrum(double k, double a) { return a > 0 && k > 0 ? std::sin(k * a) / (k * a) : 1.0; }

// the edge deflection and M_y under the load: (1/pi) integrals over k of (A + B) F and (1 - nu^2) k^2 (A + B) F,
// panel by panel between the spectrum's zeros, 4000 panels (the rest falls as (k a)^-2 at a zero: 1e-8)
double edge_integral(double a, double nu, int power) {
  auto f = [&](double k) {
    const Mode m = mode(k, nu);
    return std::pow(k, power) * std::real((m.l1 + m.l2) / m.e) * spectrum(k, a);
  };
  if (a <= 0) return gauss_kronrod<double, 31>::integrate(f, 0.0, std::numeric_limits<double>::infinity(), 15, 1e-12) / M_PI;
  double sum = 0;
  const double panel = M_PI / a;
  for (int i = 0; i < 4000; ++i) sum += gauss_kronrod<double, 31>::integrate(f, i * panel, (i + 1) * panel, 0);
  return sum / M_PI;
}

// M_x / P along the axis at x > 0: -(1/pi) integral over k of Re(p1 A e1 + p2 B e2) F
double axis_moment(double x, double a, double nu) {
  auto f = [&](double k) {
    const Mode m = mode(k, nu);
    const Complex d = Complex(0, -2) / (m.l1 + m.l2);
    return std::real(m.p1 * m.p2 * x * std::exp(-m.l1 * x) * divided(d * x) / m.e) * spectrum(k, a);
  };
  return -gauss_kronrod<double, 31>::integrate(f, 0.0, std::numeric_limits<double>::infinity(), 15, 1e-12) / M_PI;
}

}  // namespace

PlateEdgeResponse plate_edge_response(double patch, double poisson) {
  if (!(patch >= 0)) throw std::invalid_argument(fmt::format("an edge load's half-width must be >= 0, not {}", patch));
  if (!(poisson >= 0 && poisson < 0.5))
    throw std::invalid_argument(fmt::format("a Poisson ratio must be in [0, 0.5), not {}", poisson));
  PlateEdgeResponse r;
  r.deflection = edge_integral(patch, poisson, 0);
  r.radial_moment = patch > 0 ? (1 - poisson * poisson) * edge_integral(patch, poisson, 2)
                              : std::numeric_limits<double>::infinity();
  // the largest |M_x| along the axis: on a grid of 0.01 l, then the parabola through its neighbours
  double best = 0, at = 0, h = 0.01, prev = 0, next = 0;
  for (double x = h; x <= 4.0; x += h) {
    const double m = std::abs(axis_moment(x, patch, poisson));
    if (m > best) {
      best = m;
      at = x;
    }
  }
  prev = std::abs(axis_moment(at - h, patch, poisson));
  next = std::abs(axis_moment(at + h, patch, poisson));
  const double curv = prev - 2 * best + next;
  r.circumferential_moment = best;
  r.circumferential_distance = curv < 0 ? at - h * (next - prev) / (2 * curv) : at;
  return r;
}

PlateEdgeBreak plate_edge_breaking_load(double half_width, double thickness, double elastic_modulus,
                                        double poisson_ratio, double bending_strength, double water_density,
                                        double gravity) {
  const double l = characteristic_length(thickness, elastic_modulus, poisson_ratio, water_density, gravity);
  const PlateEdgeResponse r = plate_edge_response(half_width / l, poisson_ratio);
  const double capacity = bending_strength * thickness * thickness / 6.0;  // N m per m
  return PlateEdgeBreak{capacity / r.radial_moment, capacity / r.circumferential_moment,
                        r.circumferential_distance * l};
}

}  // namespace icedem
