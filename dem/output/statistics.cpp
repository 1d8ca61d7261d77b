// Load statistics: zero-phase Butterworth low-pass, peak detection by prominence and
// separation, and window statistics (docs/model/validation_targets.md §7).
#include "dem/output/statistics.hpp"

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace icedem {

namespace {

std::string num(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

/// Coefficients of a 2nd-order digital low-pass, a0 normalised to 1.
struct Biquad {
  double b0, b1, b2;  // numerator
  double a1, a2;      // denominator (a0 = 1)

  /// Runs the filter over `x` in place (direct form II transposed), starting from the
  /// steady state of a constant input equal to x[0] so that the output starts without a jump.
  void run(std::vector<double>& x) const {
    // steady state of a constant input u (DC gain 1): z1 = (b1 + b2 - a1 - a2) u, z2 = (b2 - a2) u
    double z1 = (b1 + b2 - a1 - a2) * x.front();
    double z2 = (b2 - a2) * x.front();
    for (double& v : x) {
      const double in = v;
      const double out = b0 * in + z1;
      z1 = b1 * in - a1 * out + z2;
      z2 = b2 * in - a2 * out;
      v = out;
    }
  }
};

/// 2nd-order Butterworth low-pass by the bilinear transform with prewarping (the design of
/// scipy.signal.butter(2, fc / f_nyquist)): K = tan(pi fc dt), Q = 1/sqrt(2).
Biquad butterworth2(double dt, double cutoff_hz) {
  const double k = std::tan(kPi * cutoff_hz * dt);
  const double q = 1.0 / std::sqrt(2.0);
  const double norm = 1.0 / (1.0 + k / q + k * k);
  Biquad f;
  f.b0 = k * k * norm;
  f.b1 = 2.0 * f.b0;
  f.b2 = f.b0;
  f.a1 = 2.0 * (k * k - 1.0) * norm;
  f.a2 = (1.0 - k / q + k * k) * norm;
  return f;
}

/// Topographic prominence of the peak at index p (scipy.signal.peak_prominences, no window):
/// the height above the higher of the two lowest points reached on each side before the
/// signal rises above the peak or ends.
double prominence(const std::vector<double>& x, std::size_t p) {
  double left_min = x[p];
  for (std::size_t i = p + 1; i-- > 0;) {
    if (x[i] > x[p]) break;
    left_min = std::min(left_min, x[i]);
  }
  double right_min = x[p];
  for (std::size_t i = p; i < x.size(); ++i) {
    if (x[i] > x[p]) break;
    right_min = std::min(right_min, x[i]);
  }
  return x[p] - std::max(left_min, right_min);
}

}  // namespace

std::vector<double> lowpass(const std::vector<double>& x, double dt, double cutoff_hz) {
  if (cutoff_hz <= 0.0) return x;
  if (!(dt > 0.0)) throw std::invalid_argument("lowpass: sample spacing dt = " + num(dt) +
                                               " s, expected > 0");
  const double nyquist = 0.5 / dt;
  if (cutoff_hz >= nyquist)
    throw InputError("low-pass cutoff " + num(cutoff_hz) +
                     " Hz must be below the Nyquist frequency 1/(2 dt) = " + num(nyquist) +
                     " Hz of the load series (dt = " + num(dt) + " s)");
  const std::size_t n = x.size();
  if (n < 2) return x;

  // pad both ends by odd reflection over ~3/fc (the filter rings down in ~0.2/fc), so the
  // ends continue the local trend instead of jumping to zero
  const double pad_samples = std::ceil(3.0 / (cutoff_hz * dt));
  const std::size_t pad = std::min<std::size_t>(
      n - 1, static_cast<std::size_t>(std::max(9.0, std::min(pad_samples, 1e9))));
  std::vector<double> ext(n + 2 * pad);
  for (std::size_t j = 0; j < pad; ++j) {
    ext[pad - 1 - j] = 2.0 * x.front() - x[j + 1];
    ext[pad + n + j] = 2.0 * x.back() - x[n - 2 - j];
  }
  std::copy(x.begin(), x.end(), ext.begin() + static_cast<std::ptrdiff_t>(pad));

  // forward then backward: the phase shifts cancel, the gain is squared
  const Biquad filter = butterworth2(dt, cutoff_hz);
  filter.run(ext);
  std::reverse(ext.begin(), ext.end());
  filter.run(ext);
  std::reverse(ext.begin(), ext.end());
  return std::vector<double>(ext.begin() + static_cast<std::ptrdiff_t>(pad),
                             ext.begin() + static_cast<std::ptrdiff_t>(pad + n));
}

std::vector<std::size_t> find_peaks(const std::vector<double>& x, double min_prominence,
                                    std::size_t min_separation) {
  const std::size_t n = x.size();
  std::vector<std::size_t> peaks;
  if (n < 3) return peaks;

  // local maxima; a flat top counts once, at its middle
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (!(x[i - 1] < x[i])) continue;
    std::size_t ahead = i + 1;
    while (ahead + 1 < n && x[ahead] == x[i]) ++ahead;
    if (x[ahead] < x[i]) {
      peaks.push_back((i + ahead - 1) / 2);
      i = ahead;
    }
  }

  // prominence first: a tall but shallow bump must not suppress a real peak nearby
  peaks.erase(std::remove_if(peaks.begin(), peaks.end(),
                             [&](std::size_t p) { return prominence(x, p) < min_prominence; }),
              peaks.end());
  if (min_separation <= 1 || peaks.size() < 2) return peaks;

  // separation: keep the highest peaks, drop lower ones closer than min_separation
  std::vector<std::size_t> order(peaks.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return x[peaks[a]] > x[peaks[b]]; });
  std::vector<bool> keep(peaks.size(), true);
  for (std::size_t j : order) {
    if (!keep[j]) continue;
    for (std::size_t k = j; k-- > 0 && peaks[j] - peaks[k] < min_separation;) keep[k] = false;
    for (std::size_t k = j + 1; k < peaks.size() && peaks[k] - peaks[j] < min_separation; ++k)
      keep[k] = false;
  }
  std::vector<std::size_t> kept;
  for (std::size_t j = 0; j < peaks.size(); ++j)
    if (keep[j]) kept.push_back(peaks[j]);
  return kept;
}

LoadStatistics load_statistics(const std::vector<double>& time, const std::vector<double>& load,
                               double window_start, double window_end, double lowpass_hz,
                               double min_peak_separation_s) {
  const std::size_t n = time.size();
  if (load.size() != n)
    throw std::invalid_argument("load_statistics: " + std::to_string(n) + " times but " +
                                std::to_string(load.size()) + " load samples");

  // window: contiguous samples in [start, end]; a sample within 1e-6 dt of a bound counts as
  // inside it, so that t = i * dt rounding does not drop the boundary sample
  const double dt = n >= 2 ? (time.back() - time.front()) / static_cast<double>(n - 1) : 0.0;
  const double slack = 1e-6 * std::abs(dt);
  const bool to_end = window_end <= 0.0;
  std::size_t first = 0;
  while (first < n && time[first] < window_start - slack) ++first;
  std::size_t last = first;  // one past the window
  while (last < n && (to_end || time[last] <= window_end + slack)) ++last;
  const std::size_t samples = last - first;
  if (samples < 2) {
    const std::string end_text = to_end ? "end of record" : num(window_end);
    const std::string record =
        n == 0 ? "the load record is empty"
               : "the load record covers t = [" + num(time.front()) + ", " + num(time.back()) +
                     "] s";
    throw InputError("stats.window_start_travel: the analysis window t = [" +
                     num(window_start) + ", " + end_text + "] s holds " +
                     std::to_string(samples) + " sample(s), expected at least 2; " + record +
                     ". Start the window earlier or run longer (time.duration)");
  }

  // filter the whole record, then cut: the window edges see no filter start-up
  const std::vector<double> signal = lowpass_hz > 0.0 ? lowpass(load, dt, lowpass_hz) : load;
  const std::vector<double> w(signal.begin() + static_cast<std::ptrdiff_t>(first),
                              signal.begin() + static_cast<std::ptrdiff_t>(last));

  LoadStatistics s{};
  s.samples = samples;
  s.window_start = time[first];
  s.window_end = time[last - 1];
  s.window_s = s.window_end - s.window_start;
  s.lowpass_hz = lowpass_hz > 0.0 ? lowpass_hz : 0.0;
  s.mean = std::accumulate(w.begin(), w.end(), 0.0) / static_cast<double>(samples);
  double sq = 0.0;
  for (double v : w) sq += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(sq / static_cast<double>(samples));
  const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
  s.min = *lo;
  s.max = *hi;

  // peaks: prominence >= 1 sigma, separation >= min_peak_separation_s (section 7)
  const std::size_t separation =
      min_peak_separation_s > 0.0 && dt > 0.0
          ? static_cast<std::size_t>(std::ceil(min_peak_separation_s / dt - 1e-9))
          : 1;
  const std::vector<std::size_t> peaks = find_peaks(w, s.std, separation);
  s.peaks = peaks.size();
  s.peak_interval_s = peaks.size() >= 2
                          ? (time[first + peaks.back()] - time[first + peaks.front()]) /
                                static_cast<double>(peaks.size() - 1)
                          : std::numeric_limits<double>::quiet_NaN();
  return s;
}

}  // namespace icedem
