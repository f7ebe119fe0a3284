#include "filter_table.h"

#include "flatten_adapter.h"
#include "quasidev_adapter.h"
#include "segment_adapter.h"

namespace qdml {

const std::vector<FilterSpec>& filter_table() {
  static const std::vector<FilterSpec> table = {approximate_filter(), segment_filter(),
                                                flatten_filter()};
  return table;
}

}  // namespace qdml
