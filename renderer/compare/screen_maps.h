#pragma once
// The pictures of the screen-space measures (screen_measures.h): every run's seed-0 LDR- and
// HDR-FLIP maps on the heat ramp over FLIP's whole range [0, 1], and its luminance error's 2-D
// power spectrum (mean over seeds, DC at the centre) on the heat ramp in log10 power, one scale
// per spp shared by all samplers. plot_compare.py adds the colour bars.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

namespace pdrt {

// The W x H spectrum (power_spectrum layout, DC at (0, 0)) moved so that DC is at (W / 2, H / 2)
// and frequency grows outwards: row y holds fy = (y - H / 2) / H, column x fx = (x - W / 2) / W.
std::vector<double> centred_spectrum(const std::vector<double>& power, int W, int H);

// Writes every run's flip_ldr_file, flip_hdr_file and spectrum_file, and fills
// results.spectrum_scale. Needs results.runs.
void write_screen_maps(const ReportContext& ctx, CompareResults& results);

}  // namespace pdrt
