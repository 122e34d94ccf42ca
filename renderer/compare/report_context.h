#pragma once
// What every stage of `pdrt compare`'s report reads (compare_report.h): the scene, the
// options, the image size, where the jobs' renders come from, and the progress lines.
#include "renderer/compare/compare.h"
#include "renderer/compare/compare_job.h"
#include "renderer/render/film.h"

#include <string>
#include <vector>

namespace pdrt {

struct ReportContext {
  const SceneDesc& base;
  const CompareOptions& o;
  int width = 0, height = 0;  // every image's: the crop window's (the whole film without one)
  const CompareJobSource& source;

  // A job's render; a plan's job file of another size is refused rather than misread.
  CompareRender get(const CompareJob& job) const;
  // "pdrt compare: <line>" on stderr unless quiet.
  void say(const std::string& line) const;
  // Writes `rgb` (display values, width x height) as the report's PNG `file` (relative to o.out).
  void write_png(const std::string& file, const std::vector<float>& rgb) const;
};

// The context of a report on `base`; InputError when the crop window covers no pixel.
ReportContext report_context(const SceneDesc& base, const CompareOptions& o, const CompareJobSource& source);

// An image's display values (sRGB encoded), for the report's PNGs.
std::vector<float> display_rgb(const Image& im);

}  // namespace pdrt
