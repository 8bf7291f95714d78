#include "spatial/range_search.h"

#include "spatial/flann_kd_tree.h"
#include "spatial/hash_grid.h"

#include <stdexcept>

namespace caustica {

std::unique_ptr<RangeSearch> create_range_search(const std::string &name) {
    if (name == "hashgrid") return std::make_unique<HashGrid>();
    if (name == "flann") return std::make_unique<FlannKdTree>();
    throw std::invalid_argument("unknown range search \"" + name +
                                "\" (expected \"hashgrid\" or \"flann\")");
}

} // namespace caustica
