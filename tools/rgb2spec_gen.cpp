// Build-time generator of the RGB-to-spectrum tables (Jakob and Hanika 2019, "A Low-Dimensional
// Function Space for Efficient Spectral Upsampling", Computer Graphics Forum 38(2)).
//
// For every colour space of StandardColorSpaces and every cell of a res^3 grid over RGB, it
// finds the coefficients c of the reflectance s(l) = sigmoid(c0 t^2 + c1 t + c2), t the
// wavelength mapped to [0, 1], whose colour under the space's illuminant is the cell's RGB.
// "Colour" is measured exactly as the renderer measures it (spectrum_to_xyz: sums over every
// integer nm from 360 to 830 nm of the CIE 1931 functions, divided by CIE_Y_integral), so a
// table entry round-trips to its RGB up to the optimiser's tolerance. The error minimised is
// the CIE 1976 (L*a*b*) difference, which weighs dark and saturated colours perceptually.
//
// Each fit is a Gauss-Newton iteration with an analytic Jacobian and a backtracking line
// search. As in the paper, cells are visited along lines of increasing and decreasing
// brightness starting from a mid-grey-ish brightness, each fit starting from its neighbour's
// solution: the solutions vary smoothly, so a few iterations suffice. Lines are independent
// tasks, so the output does not depend on the number of threads.
//
// Usage: rgb2spec_gen OUTPUT_DIR RESOLUTION
// Writes OUTPUT_DIR/rgb2spec_<space>.bin (the layout of RGBToSpectrumTableData: `resolution`
// brightness values, then the coefficient array, native floats) and
// OUTPUT_DIR/rgb_to_spectrum_tables.cpp, which assembles those files into the program.

#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/named_spectra.h"
#include "spectral/standard_color_spaces.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace caustica;

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;  // rows

constexpr int NumLambda = int(LambdaMax - LambdaMin) + 1;

// Coefficients are kept below this magnitude (in normalised-wavelength units). Colours on the
// gamut boundary need infinitely steep sigmoids; capping keeps the table smooth enough to
// interpolate, at a negligible colour error for those extreme cells.
constexpr double MaxCoefficient = 200;
// Squared L*a*b* error at which a fit stops: a colour difference of 1e-4, far below visibility
// (1 is about a just-noticeable difference) and below float rounding of the stored table.
constexpr double ConvergedError = 1e-8;

// Solves a x = b by Gaussian elimination with partial pivoting; false if a is singular.
bool solve(Mat3 a, Vec3 b, Vec3 &x) {
    for (int col = 0; col < 3; ++col) {
        int pivot = col;
        for (int row = col + 1; row < 3; ++row)
            if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
        if (std::abs(a[pivot][col]) < 1e-15) return false;
        std::swap(a[col], a[pivot]);
        std::swap(b[col], b[pivot]);
        for (int row = col + 1; row < 3; ++row) {
            double f = a[row][col] / a[col][col];
            for (int k = col; k < 3; ++k) a[row][k] -= f * a[col][k];
            b[row] -= f * b[col];
        }
    }
    for (int row = 2; row >= 0; --row) {
        double sum = b[row];
        for (int k = row + 1; k < 3; ++k) sum -= a[row][k] * x[k];
        x[row] = sum / a[row][row];
    }
    return true;
}

// CIE 1976 L*a*b* lightness function and its derivative.
constexpr double LabDelta = 6.0 / 29.0;
double lab_f(double t) {
    return t > LabDelta * LabDelta * LabDelta ? std::cbrt(t)
                                              : t / (3 * LabDelta * LabDelta) + 4.0 / 29.0;
}
double lab_f_derivative(double t) {
    if (t > LabDelta * LabDelta * LabDelta) {
        double c = std::cbrt(t);
        return 1 / (3 * c * c);
    }
    return 1 / (3 * LabDelta * LabDelta);
}

// Fits sigmoid polynomials to the colours of one colour space.
class ColorSpaceFit {
  public:
    explicit ColorSpaceFit(const ColorSpaceDefinition &def) {
        SpectrumPtr illuminant = get_named_spectrum(std::string(def.illuminant));
        if (!illuminant) throw std::runtime_error("no illuminant " + std::string(def.illuminant));
        for (int i = 0; i < NumLambda; ++i) {
            float lambda = LambdaMin + float(i);
            t_[i] = float((double(lambda) - LambdaMin) / (LambdaMax - LambdaMin));
            double e = (*illuminant)(lambda) / double(CIE_Y_integral);
            weight_x_[i] = float(cie_x()(lambda) * e);
            weight_y_[i] = float(cie_y()(lambda) * e);
            weight_z_[i] = float(cie_z()(lambda) * e);
            white_[0] += weight_x_[i];
            white_[1] += weight_y_[i];
            white_[2] += weight_z_[i];
        }
        // The white point and matrix as RGBColorSpace computes them (up to float rounding).
        XYZ white{float(white_[0]), float(white_[1]), float(white_[2])};
        Matrix3 m = rgb_to_xyz_matrix(def.red, def.green, def.blue, white);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) xyz_from_rgb_[r][c] = m[r][c];
    }

    // Refines c (normalised-wavelength coefficients) towards the reflectance of colour rgb.
    void fit(const Vec3 &rgb, Vec3 &c) const {
        Vec3 xyz{};
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) xyz[r] += xyz_from_rgb_[r][k] * rgb[k];
        Vec3 target = lab(xyz);

        Vec3 residual;
        Mat3 jacobian;
        double error = evaluate(c, target, residual, jacobian);
        for (int iteration = 0; iteration < 30 && error > ConvergedError; ++iteration) {
            Vec3 step;
            if (!solve(jacobian, residual, step)) break;
            // Backtrack until the error decreases: a full Gauss-Newton step can overshoot
            // where the sigmoid saturates.
            double previous_error = error;
            for (double scale = 1; scale >= 1.0 / 32; scale *= 0.5) {
                Vec3 trial{c[0] - scale * step[0], c[1] - scale * step[1], c[2] - scale * step[2]};
                double largest =
                    std::max({std::abs(trial[0]), std::abs(trial[1]), std::abs(trial[2])});
                if (largest > MaxCoefficient)
                    for (double &v : trial) v *= MaxCoefficient / largest;
                Vec3 trial_residual;
                Mat3 trial_jacobian;
                double trial_error = evaluate(trial, target, trial_residual, trial_jacobian);
                if (trial_error < error) {
                    c = trial;
                    residual = trial_residual;
                    jacobian = trial_jacobian;
                    error = trial_error;
                    break;
                }
            }
            // Colours outside what the model reaches (beyond the spectral locus, or needing
            // coefficients past the cap) stall at a non-zero error: stop once progress is slow.
            if (error > 0.99 * previous_error) break;
        }
    }

  private:
    Vec3 lab(const Vec3 &xyz) const {
        double fx = lab_f(xyz[0] / white_[0]), fy = lab_f(xyz[1] / white_[1]),
               fz = lab_f(xyz[2] / white_[2]);
        return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
    }

    // Squared L*a*b* error of coefficients c, with the residual and its Jacobian in c.
    double evaluate(const Vec3 &c, const Vec3 &target, Vec3 &residual, Mat3 &jacobian) const {
        // XYZ of the reflectance and its derivatives in c; the sigmoid's derivative is
        // 1 / (2 (1 + x^2)^(3/2)).
        // Single precision, 4 wavelengths per SSE instruction: the sums' rounding error (~1e-7
        // relative) is far below the convergence tolerance. The loop carries no dependence
        // but the sums, so it vectorises (-fopenmp-simd; -fno-math-errno for the sqrt).
        float x = 0, y = 0, z = 0, dx0 = 0, dx1 = 0, dx2 = 0, dy0 = 0, dy1 = 0, dy2 = 0, dz0 = 0,
              dz1 = 0, dz2 = 0;
        const float c0 = float(c[0]), c1 = float(c[1]), c2 = float(c[2]);
#pragma omp simd reduction(+ : x, y, z, dx0, dx1, dx2, dy0, dy1, dy2, dz0, dz1, dz2)
        for (int i = 0; i < NumLambda; ++i) {
            float t = t_[i];
            float p = (c0 * t + c1) * t + c2;
            float inv = 1 / std::sqrt(1 + p * p);
            float s = 0.5f + 0.5f * p * inv;
            float ds2 = 0.5f * inv * inv * inv, ds1 = ds2 * t, ds0 = ds1 * t;
            float wx = weight_x_[i], wy = weight_y_[i], wz = weight_z_[i];
            x += s * wx;
            y += s * wy;
            z += s * wz;
            dx0 += ds0 * wx;
            dx1 += ds1 * wx;
            dx2 += ds2 * wx;
            dy0 += ds0 * wy;
            dy1 += ds1 * wy;
            dy2 += ds2 * wy;
            dz0 += ds0 * wz;
            dz1 += ds1 * wz;
            dz2 += ds2 * wz;
        }
        const double dx[3] = {dx0, dx1, dx2}, dy[3] = {dy0, dy1, dy2}, dz[3] = {dz0, dz1, dz2};
        Vec3 value = lab({x, y, z});
        double gx = lab_f_derivative(x / white_[0]) / white_[0];
        double gy = lab_f_derivative(y / white_[1]) / white_[1];
        double gz = lab_f_derivative(z / white_[2]) / white_[2];
        for (int k = 0; k < 3; ++k) {
            jacobian[0][k] = 116 * gy * dy[k];
            jacobian[1][k] = 500 * (gx * dx[k] - gy * dy[k]);
            jacobian[2][k] = 200 * (gy * dy[k] - gz * dz[k]);
        }
        double error = 0;
        for (int k = 0; k < 3; ++k) {
            residual[k] = value[k] - target[k];
            error += residual[k] * residual[k];
        }
        return error;
    }

    std::array<float, NumLambda> t_{}, weight_x_{}, weight_y_{}, weight_z_{};
    Vec3 white_{};
    Mat3 xyz_from_rgb_{};
};

double smoothstep(double x) { return x * x * (3 - 2 * x); }

// The table for one colour space: brightness values, then [3][res][res][res][3] coefficients
// in nm units.
std::vector<float> optimize_table(const ColorSpaceDefinition &def, int res) {
    ColorSpaceFit fit(def);
    std::vector<double> scale(res);
    for (int k = 0; k < res; ++k) scale[k] = smoothstep(smoothstep(double(k) / (res - 1)));

    std::vector<float> table(size_t(res) + 3 * size_t(res) * res * res * 3);
    float *coefficients = table.data() + res;
    auto store = [&](int l, int k, int j, int i, const Vec3 &c) {
        // s = sigmoid(c0 t^2 + c1 t + c2) with t = (lambda - a) / d, rewritten in lambda.
        double a = LambdaMin, d = LambdaMax - LambdaMin;
        double c0 = c[0] / (d * d), c1 = c[1] / d - 2 * a * c[0] / (d * d);
        double c2 = c[2] - c[1] * a / d + c[0] * a * a / (d * d);
        float *out = coefficients + 3 * (((size_t(l) * res + k) * res + j) * res + i);
        out[0] = float(c0);
        out[1] = float(c1);
        out[2] = float(c2);
    };

    std::atomic<int> next_line{0};
    auto worker = [&] {
        for (int line; (line = next_line++) < 3 * res;) {
            int l = line / res, j = line % res;
            for (int i = 0; i < res; ++i) {
                double x = double(i) / (res - 1), y = double(j) / (res - 1);
                auto rgb_at = [&](int k) {
                    Vec3 rgb;
                    rgb[l] = scale[k];
                    rgb[(l + 1) % 3] = x * scale[k];
                    rgb[(l + 2) % 3] = y * scale[k];
                    return rgb;
                };
                const int start = res / 5;
                Vec3 c{0, 0, 0}, c_start;
                for (int k = start; k < res; ++k) {
                    fit.fit(rgb_at(k), c);
                    store(l, k, j, i, c);
                    if (k == start) c_start = c;
                }
                c = c_start;
                for (int k = start - 1; k >= 0; --k) {
                    fit.fit(rgb_at(k), c);
                    store(l, k, j, i, c);
                }
            }
        }
    };
    unsigned n_threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < n_threads; ++t) threads.emplace_back(worker);
    for (std::thread &t : threads) t.join();

    for (int k = 0; k < res; ++k) table[k] = float(scale[k]);
    return table;
}

std::string symbol_name(std::string_view space) {
    std::string name = "caustica_rgb2spec_";
    for (char ch : space) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    return name;
}

// Writes through a temporary file so that an interrupted run leaves no truncated output.
void write_file(const std::filesystem::path &path, const void *data, size_t size) {
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(static_cast<const char *>(data), std::streamsize(size));
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
    }
    std::filesystem::rename(tmp, path);
}

// The path as it goes between quotes in the .incbin directive of the generated source.
std::string incbin_path(const std::filesystem::path &file) {
    std::string path = std::filesystem::absolute(file).string();
    if (path.find_first_of("\"\\\n") != std::string::npos)
        throw std::runtime_error("output path contains a quote or backslash: " + path);
    return path;
}

} // namespace

int main(int argc, char **argv) {
    if (argc != 3) {
        std::cerr << "usage: " << argv[0] << " OUTPUT_DIR RESOLUTION\n";
        return 2;
    }
    std::filesystem::path dir = argv[1];
    int res = std::atoi(argv[2]);
    if (res < 3) {
        std::cerr << "rgb2spec_gen: resolution must be at least 3\n";
        return 2;
    }
    try {
        std::filesystem::create_directories(dir);
        std::string source = "// Generated by tools/rgb2spec_gen.cpp at resolution " +
                             std::to_string(res) +
                             "; do not edit.\n"
                             "#include \"spectral/rgb_to_spectrum_data.h\"\n\n"
                             "// The optimiser's binary tables, assembled into read-only data.\n";
        std::string lookup;
        for (const ColorSpaceDefinition &def : StandardColorSpaces) {
            std::vector<float> table = optimize_table(def, res);
            std::filesystem::path bin = dir / ("rgb2spec_" + std::string(def.name) + ".bin");
            write_file(bin, table.data(), table.size() * sizeof(float));
            std::string sym = symbol_name(def.name);
            source += "asm(\".section .rodata\\n.balign 16\\n.globl " + sym + "\\n.hidden " + sym +
                      "\\n" + sym + ":\\n.incbin \\\"" + incbin_path(bin) +
                      "\\\"\\n.previous\\n\");\n";
            source += "extern \"C\" const float " + sym + "[];\n";
            lookup += "    if (color_space == \"" + std::string(def.name) +
                      "\") {\n"
                      "        static const RGBToSpectrumTableData data{" +
                      std::to_string(res) + ", " + sym + ", " + sym + " + " + std::to_string(res) +
                      "};\n"
                      "        return &data;\n    }\n";
            std::cout << "rgb2spec_gen: " << def.name << " done\n";
        }
        source +=
            "\nnamespace caustica {\n\n"
            "const RGBToSpectrumTableData *rgb_to_spectrum_table_data(std::string_view "
            "color_space) {\n" +
            lookup + "    return nullptr;\n}\n\n} // namespace caustica\n";
        write_file(dir / "rgb_to_spectrum_tables.cpp", source.data(), source.size());
    } catch (const std::exception &e) {
        std::cerr << "rgb2spec_gen: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
