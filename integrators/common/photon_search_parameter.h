// The "photonsearch" parameter of the photon integrators (sppm, bpm, vcm).
#pragma once

#include "core/error.h"
#include "params/parameters.h"
#include "spatial/photon_map.h"

#include <string>

namespace caustica {

// "hashgrid" (the default) or "flann"; anything else is an error at the parameter's location.
inline PhotonSearch read_photon_search(const ParameterDictionary &params) {
    const std::string name = params.get_one_string("photonsearch", "hashgrid");
    if (name == "hashgrid") return PhotonSearch::HashGrid;
    if (name == "flann") return PhotonSearch::FlannKdTree;
    throw InputError(params.location("photonsearch"), "\"photonsearch\" must be \"hashgrid\" or \"flann\"");
}

} // namespace caustica
