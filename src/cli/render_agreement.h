// Whether two integrators' renders of one scene agree within their noise. Each render is the
// average of two independent renders (two_run_noise.h), whose half-difference measures its
// noise, so no reference is needed. Two tests, each at a false-alarm rate of
// kAgreementFalseAlarmRate when the renders agree and the noise is normal:
//  - the image mean over pixels and channels, z from (m_1 - m_2) / sqrt(Var m_1 + Var m_2): a
//    bias anywhere in the image (a wrong normalisation, a missing kind of light path);
//  - the mean of each block of pixels (16x16, smaller on small images), whose largest |z| is set
//    against the Bonferroni threshold for the number of blocks: a local bias (a missing
//    caustic) too small to move the image mean.
// Every z is normal-equivalent: the variances are themselves estimated, from the blocks, so the
// ratio follows Student's t rather than the normal distribution, and is converted to the normal
// value with the same tail probability. Small images (few blocks) thus need larger differences.
#pragma once

#include "cli/two_run_noise.h"

#include <string>

namespace caustica {

constexpr double kAgreementFalseAlarmRate = 1e-4;

struct Agreement {
    std::string first, second;     // integrator names
    double relative_difference = 0; // (m_1 - m_2) / ((m_1 + m_2) / 2) of the image means
    double z = 0;                  // of the image-mean difference (normal-equivalent)
    double threshold = 0;          // |z| above it: disagreement
    int block_size = 0, blocks = 0;
    int worst_block_x = 0, worst_block_y = 0; // top-left pixel of the block with the largest |z|
    double worst_block_z = 0;
    double block_threshold = 0; // Bonferroni: the two-sided normal quantile of rate / blocks
    bool agree = true;          // neither test exceeds its threshold
};

// Both pairs of renders must have the same size.
Agreement check_agreement(const std::string &first, const TwoRuns &first_runs, const std::string &second,
                          const TwoRuns &second_runs);

// E.g. "DISAGREE: pt and vcm differ by 3.1% in image mean (z = 7.2, threshold 3.9); worst
// 16x16 block at (32, 48): z = 9.5 (threshold 5.1)", or the same beginning with "agree".
std::string agreement_sentence(const Agreement &agreement);

// z such that a standard normal variable exceeds |z| with probability p (0 < p <= 1).
double two_sided_normal_quantile(double p);

} // namespace caustica
