// The noise of a render measured without a reference, from two independent renders A and B of
// the same image (different seeds). Their average M = (A + B) / 2 is the image reported, and
// their half-difference H = (A - B) / 2 is pure noise: for independent, identically distributed
// renders E[H_i H_j] = (Cov(A_i, A_j) + Cov(B_i, B_j)) / 4 = Cov(M_i, M_j) for any two pixel
// channels i and j, whatever the image's (unknown) expected value. So H_i^2 estimates the
// variance of M_i without bias: it is the textbook sample variance of n = 2 values,
// (A_i - B_i)^2 / 2, divided by n for the variance of their mean; the "dual buffer" estimate of
// denoisers (Rousselle, Knaus and Zwicker 2012, "Adaptive rendering with non-local means
// filtering"). It sees variance only: a bias both renders share (a bug, or the blur of photon
// merging) is invisible to it, which is what render_agreement.h checks between integrators.
#pragma once

#include "film/image.h"

namespace caustica {

// RMSE and relative MSE, as image_difference (commands.h) defines them.
struct RenderError {
    double rmse = 0, relative_mse = 0;
};

struct TwoRuns {
    Image mean;            // (A + B) / 2
    Image half_difference; // (A - B) / 2

    // A and B must have the same size.
    TwoRuns(const Image &a, const Image &b);
};

// The expected error of `runs.mean` against the exact image, estimated from H: RMSE
// sqrt(mean of H^2), relative MSE the mean over pixels and channels of H^2 / (M^2 + 0.01). M
// stands in for the unknown reference in the denominator, so the relative MSE reads slightly
// low (by a factor about 1 + Var(M) / (r^2 + 0.01)) where the noise is large against the value.
RenderError estimated_error(const TwoRuns &runs);

// H^2 per pixel and channel: the estimated variance of the mean image, for error images.
Image estimated_variance(const TwoRuns &runs);

} // namespace caustica
