#include "film/spectral_buckets.h"

#include <algorithm>
#include <cstdio>

namespace caustica {

std::string SpectralBuckets::channel_name(int bucket) const {
    char centre[32];
    std::snprintf(centre, sizeof centre, "%.3fnm", double(this->centre(bucket)));
    std::string name = std::string("S0.") + centre;
    std::replace(name.begin() + 3, name.end(), '.', ',');
    return name;
}

} // namespace caustica
