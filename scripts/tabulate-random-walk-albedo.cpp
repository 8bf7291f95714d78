// Tabulates the total diffuse reflectance R(alpha) of a semi-infinite, isotropically scattering
// medium of single-scattering albedo alpha under the boundary that the Disney material's
// random-walk subsurface uses (src/materials/disney_bxdf.h):
//   - light enters through a Lambertian transmission lobe, so the first flight direction is
//     cosine-distributed into the medium;
//   - a walk that reaches the boundary leaves with probability 41/42 (the albedo of the exit lobe
//     (1/pi)(1 - (1 - cos)^5 / 2)) and is otherwise reflected back in, cosine-distributed (the
//     internal reflection lobe of albedo 1/42).
// R depends on alpha only (the mean free path sets the scale), so one table serves every
// scatterDistance. The material inverts it to find the albedo that reflects a given baseColor.
//
// Build and run (prints the table in src/materials/random_walk_albedo.cpp):
//   g++ -O2 -std=c++20 scripts/tabulate-random-walk-albedo.cpp -o /tmp/tabulate && /tmp/tabulate
// Each entry averages 2^21 walks with weights (alpha per scattering event, Russian roulette below
// 1e-3): the standard error of each R is below 4e-4.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

int main() {
    const int entries = 65;
    const long walks = 1L << 21;
    std::printf("// R(alpha) at alpha = 1 - s^2, s = i / %d (i = 0 .. %d)\n", entries - 1, entries - 1);
    for (int i = 0; i < entries; ++i) {
        const double s = double(i) / (entries - 1), alpha = 1 - s * s;
        std::mt19937_64 rng(1000 + i);
        std::uniform_real_distribution<double> uniform(0, 1);
        auto cosine_inwards = [&](double &dz) { dz = -std::sqrt(uniform(rng)); };
        double total = 0;
        for (long w = 0; w < walks; ++w) {
            if (i == 0) { total += 1; continue; }  // alpha = 1: every walk leaves eventually
            double z = 0, dz, weight = 1;
            cosine_inwards(dz);
            while (true) {
                double distance = -std::log(1 - uniform(rng));
                z += dz * distance;
                if (z >= 0) {
                    if (uniform(rng) < 41.0 / 42.0) {
                        total += weight;
                        break;
                    }
                    z = 0;
                    cosine_inwards(dz);
                    continue;
                }
                weight *= alpha;
                if (weight < 1e-3) {
                    if (uniform(rng) < 0.5) break;
                    weight *= 2;
                }
                dz = 1 - 2 * uniform(rng);  // isotropic: the z cosine is uniform
            }
        }
        std::printf("%.6f,%s", total / walks, i % 8 == 7 ? "\n" : " ");
    }
    std::printf("\n");
}
