// The command's printable PDF of a pattern: the paper and model unit chosen by the user turned
// into the page grid (page_tiles.h) and the document (pdf_writer.h), with a one-line summary
// for the log.
#pragma once

#include <string>

#include "choices.h"
#include "flatten/pattern.h"

namespace qd::pdf {

constexpr int kMaxPages = 1000;  // more means the unit is wrong, not a pattern to print

struct PrintablePdf {
  std::string bytes;
  std::string summary;  // "pdf: 7 pages of a4 (assembly map + 2 rows x 3 columns of tiles)"
};

// Throws qd::common::Error for PatternUnit::Model or when it would take more than kMaxPages pages.
PrintablePdf printable_pdf(const flatten::Pattern& pattern, params::Paper paper,
                           params::PatternUnit unit);

}  // namespace qd::pdf
