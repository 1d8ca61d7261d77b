// Load statistics over an analysis window: zero-phase low-pass, peak detection, and the
// mean / standard deviation / extremes the paper reports (docs/model/validation_targets.md §7).
#pragma once

#include <cstddef>
#include <vector>

namespace icedem {

/// Returns `x` low-passed by a 2nd-order Butterworth filter run forward and backward
/// (zero phase, effective order 4, amplitude response 1 / (1 + (f/fc)^4) after the bilinear
/// prewarp). The ends are padded by odd reflection and the filter starts in its steady state,
/// so a slow signal keeps its end values. `dt` is the sample spacing (s, > 0). A cutoff <= 0
/// returns a copy; a cutoff at or above the Nyquist frequency 1/(2 dt) throws InputError.
std::vector<double> lowpass(const std::vector<double>& x, double dt, double cutoff_hz);

/// Returns the indices (ascending) of the peaks of `x`: local maxima (the middle of a flat
/// top counts once; the first and last samples never do) whose topographic prominence is at
/// least `min_prominence` and that lie at least `min_separation` samples from any higher kept
/// peak. Prominence is filtered first, then separation, keeping the highest peaks (the
/// definitions of scipy.signal.find_peaks, which applies them in the opposite order).
std::vector<std::size_t> find_peaks(const std::vector<double>& x, double min_prominence,
                                    std::size_t min_separation);

/// Statistics of a load signal over an analysis window.
struct LoadStatistics {
  double mean;             // N, over the window (filtered signal if lowpass_hz > 0)
  double std;              // N, population standard deviation (divides by samples)
  double max;              // N
  double min;              // N
  double window_start;     // s, time of the first sample in the window
  double window_end;       // s, time of the last sample in the window
  double window_s;         // s, window_end - window_start
  std::size_t samples;     // samples in the window
  std::size_t peaks;       // detected peaks (prominence >= std, separation >= the minimum)
  double peak_interval_s;  // s, mean spacing of detected peaks (NaN if fewer than 2)
  double lowpass_hz;       // Hz, cutoff used (<= 0: none)
};

/// Computes LoadStatistics of `load` (N) sampled at `time` (s, uniform spacing) over the
/// samples with window_start <= t <= window_end (window_end <= 0: to the end of the record).
/// The whole record is low-passed first when lowpass_hz > 0, so the window edges carry no
/// filter transient. Peaks need a prominence of one standard deviation of the window signal
/// and a spacing of min_peak_separation_s (docs/model/validation_targets.md §7: ~1 sigma, ~0.5 L/v).
/// Throws InputError naming `stats.window_start_travel` if the window holds fewer than 2
/// samples, std::invalid_argument if the two vectors differ in length.
LoadStatistics load_statistics(const std::vector<double>& time, const std::vector<double>& load,
                               double window_start, double window_end, double lowpass_hz,
                               double min_peak_separation_s);

}  // namespace icedem
