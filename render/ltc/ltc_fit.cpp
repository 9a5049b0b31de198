#include "ltc_fit.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>

namespace candela::ltc {
namespace {

constexpr double kPi = std::numbers::pi;

double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
double length(const Vec3& v) {
    return std::sqrt(dot(v, v));
}
Vec3 scale(const Vec3& v, double s) {
    return {v.x * s, v.y * s, v.z * s};
}
Vec3 add(const Vec3& a, const Vec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec3 normalize(const Vec3& v) {
    return scale(v, 1.0 / length(v));
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                r[i][j] += a[i][k] * b[k][j];
    return r;
}

// eq. 3
double ggx(double a2, double NoH) {
    const double d = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (kPi * d * d);
}

// Smith G1 of GGX (exact), the visible-normal density's normaliser.
double smithG1(double a2, double NoV) {
    return 2.0 * NoV / (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV));
}

// brdf.glsl's visibilitySmithGgxCorrelated, in double.
double visibilityCorrelated(double a2, double NoV, double NoL) {
    const double lambdaV = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
    const double lambdaL = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / (lambdaV + lambdaL);
}

// The stratified point (i, j) of an n x n grid in the unit square.
double cellCentre(int i, int n) {
    return (i + 0.5) / n;
}

// Balance-heuristic estimate of the integral of h(p, q) over the sphere, sampling the lobe
// (density lobe.pdf) and the transformed cosine (density q itself).
template <class H>
double integrateBoth(const GgxLobe& lobe, double magnitude, const TransformedCosine& ltc, int n,
                     H h) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double u1 = cellCentre(i, n), u2 = cellCentre(j, n);
            double lobePdf = 0.0;
            const Vec3 fromLobe = lobe.sample(u1, u2, &lobePdf);
            if (lobePdf > 0.0) {
                const double p = lobe.value(fromLobe) / magnitude;
                const double q = ltc.density(fromLobe);
                sum += h(p, q) / (lobePdf + q);
            }
            const Vec3 fromLtc = ltc.sample(u1, u2);
            const double q = ltc.density(fromLtc);
            if (q > 0.0) {
                const double p = lobe.value(fromLtc) / magnitude;
                sum += h(p, q) / (lobe.pdf(fromLtc) + q);
            }
        }
    }
    return sum / (double(n) * n);
}

// Visits the lobe's n x n stratified visible-normal samples with their weights value / pdf.
template <class Visit>
void forEachLobeSample(const GgxLobe& lobe, int n, Visit visit) {
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double pdf = 0.0;
            const Vec3 l = lobe.sample(cellCentre(i, n), cellCentre(j, n), &pdf);
            if (pdf > 0.0) visit(l, lobe.value(l) / pdf);
        }
    }
}

// The mean direction of the lobe (in the xz-plane): the frame the fitted shape lives in.
Mat3 meanDirectionFrame(const GgxLobe& lobe, int n) {
    Vec3 mean{};
    forEachLobeSample(lobe, n,
                      [&](const Vec3& l, double weight) { mean = add(mean, scale(l, weight)); });
    mean.y = 0.0;  // symmetric about the xz-plane
    const Vec3 z = length(mean) > 0.0 ? normalize(mean) : Vec3{0, 0, 1};
    const Vec3 y{0, 1, 0};
    const Vec3 x = cross(y, z);
    return Mat3{{{x.x, y.x, z.x}, {x.y, y.y, z.y}, {x.z, y.z, z.z}}};  // columns x, y, z
}

// M = F R(tilt) [[a, 0, b], [0, c, 0], [0, 0, 1]]: F the lobe's mean-direction frame, R a
// rotation about y, shape = (a, c, b, tilt).
Mat3 shapeMatrix(const Mat3& frame, const Shape& shape) {
    const double cosTilt = std::cos(shape[3]), sinTilt = std::sin(shape[3]);
    const Mat3 tilt{{{cosTilt, 0.0, sinTilt}, {0.0, 1.0, 0.0}, {-sinTilt, 0.0, cosTilt}}};
    const Mat3 s{
        {{std::abs(shape[0]), 0.0, shape[2]}, {0.0, std::abs(shape[1]), 0.0}, {0.0, 0.0, 1.0}}};
    return multiply(frame, multiply(tilt, s));
}

// Nelder-Mead simplex minimisation of f over the shape's parameters.
template <class F>
Shape minimise(F f, Shape start, Shape steps, int iterations) {
    constexpr int n = int(std::tuple_size_v<Shape>);
    std::array<Shape, n + 1> p;
    p.fill(start);
    for (int i = 0; i < n; ++i)
        p[i + 1][i] += steps[i];
    std::array<double, n + 1> v{};
    for (int i = 0; i <= n; ++i)
        v[i] = f(p[i]);
    auto blend = [](const Shape& a, const Shape& b, double t) {
        Shape r{};
        for (int i = 0; i < n; ++i)
            r[i] = a[i] + (b[i] - a[i]) * t;
        return r;
    };
    std::array<int, n + 1> order;
    for (int iteration = 0; iteration < iterations; ++iteration) {
        for (int i = 0; i <= n; ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return v[a] < v[b]; });
        const int best = order[0], worst = order[n], second = order[n - 1];
        if (std::abs(v[worst] - v[best]) <= 1e-9 * std::abs(v[best]) + 1e-14) break;
        Shape centroid{};
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < n; ++k)
                centroid[k] += p[order[i]][k] / n;
        const Shape reflected = blend(centroid, p[worst], -1.0);
        const double fr = f(reflected);
        if (fr < v[best]) {
            const Shape expanded = blend(centroid, p[worst], -2.0);
            const double fe = f(expanded);
            if (fe < fr) {
                p[worst] = expanded, v[worst] = fe;
            } else {
                p[worst] = reflected, v[worst] = fr;
            }
        } else if (fr < v[second]) {
            p[worst] = reflected, v[worst] = fr;
        } else {
            const Shape contracted = blend(centroid, p[worst], fr < v[worst] ? -0.5 : 0.5);
            const double fc = f(contracted);
            if (fc < std::min(fr, v[worst])) {
                p[worst] = contracted, v[worst] = fc;
            } else {
                for (int i = 0; i <= n; ++i) {
                    if (i == best) continue;
                    p[i] = blend(p[best], p[i], 0.5);
                    v[i] = f(p[i]);
                }
            }
        }
    }
    return p[std::min_element(v.begin(), v.end()) - v.begin()];
}

}  // namespace

Vec3 operator*(const Mat3& m, const Vec3& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

double determinant(const Mat3& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Mat3 inverse(const Mat3& m) {
    const double d = 1.0 / determinant(m);
    Mat3 r{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            // Cofactor of m[j][i] (transposed adjugate).
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            r[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) * d;
        }
    }
    return r;
}

Vec3 GgxLobe::view() const {
    return {std::sqrt(std::max(0.0, 1.0 - cosView * cosView)), 0.0, cosView};
}

double GgxLobe::value(const Vec3& l) const {
    if (l.z <= 0.0) return 0.0;
    const Vec3 h = normalize(add(view(), l));
    const double a2 = alpha * alpha;
    return ggx(a2, h.z) * visibilityCorrelated(a2, cosView, l.z) * l.z;
}

Vec3 GgxLobe::sample(double u1, double u2, double* density) const {
    const Vec3 v = view();
    // The view in the hemisphere configuration where the microsurface is a unit hemisphere.
    const Vec3 vh = normalize({alpha * v.x, alpha * v.y, v.z});
    const double lengthSquared = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lengthSquared > 0.0
                        ? scale(Vec3{-vh.y, vh.x, 0.0}, 1.0 / std::sqrt(lengthSquared))
                        : Vec3{1.0, 0.0, 0.0};
    const Vec3 t2 = cross(vh, t1);
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + vh.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = add(add(scale(t1, p1), scale(t2, p2)),
                        scale(vh, std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2))));
    const Vec3 h = normalize({alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)});
    const Vec3 l = add(scale(h, 2.0 * dot(v, h)), scale(v, -1.0));
    *density = pdf(l);
    return l;
}

double GgxLobe::pdf(const Vec3& l) const {
    const Vec3 v = view();
    const Vec3 sum = add(v, l);
    if (length(sum) == 0.0) return 0.0;
    const Vec3 h = normalize(sum);
    if (dot(v, h) <= 0.0 || h.z <= 0.0) return 0.0;
    const double a2 = alpha * alpha;
    // Visible normals G1(V) VoH D(H) / NoV, times the reflection Jacobian 1 / (4 VoH).
    return smithG1(a2, cosView) * ggx(a2, h.z) / (4.0 * cosView);
}

TransformedCosine TransformedCosine::from(const Mat3& m) {
    const Mat3 mi = inverse(m);
    return {m, mi, std::abs(determinant(mi))};
}

double TransformedCosine::density(const Vec3& w) const {
    const Vec3 original = mInverse * w;
    const double len = length(original);
    const double cosine = original.z / len;
    if (cosine <= 0.0) return 0.0;
    return cosine / kPi * jacobianScale / (len * len * len);
}

Vec3 TransformedCosine::sample(double u1, double u2) const {
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    const Vec3 cosineSample{r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1)};
    return normalize(m * cosineSample);
}

Mat3 TableCell::inverseMatrix() const {
    return Mat3{{{inverse00, 0.0, inverse02}, {0.0, 1.0, 0.0}, {inverse20, 0.0, inverse22}}};
}

double l1Distance(const GgxLobe& lobe, double magnitude, const TransformedCosine& ltc,
                  int samplesPerSide) {
    return integrateBoth(lobe, magnitude, ltc, samplesPerSide,
                         [](double p, double q) { return std::abs(p - q); });
}

void integrateMagnitude(const GgxLobe& lobe, int n, double* magnitude, double* fresnel) {
    double sumN = 0.0, sumF = 0.0;
    const Vec3 v = lobe.view();
    forEachLobeSample(lobe, n, [&](const Vec3& l, double weight) {
        const double VoH = std::clamp(dot(v, normalize(add(v, l))), 0.0, 1.0);
        sumN += weight;
        sumF += weight * std::pow(1.0 - VoH, 5.0);
    });
    *magnitude = sumN / (double(n) * n);
    *fresnel = sumF / (double(n) * n);
}

CellFit fitCell(double roughness, double cosView, const FitOptions& options, const Shape* start) {
    const double r = std::clamp(roughness, kMinRoughness, 1.0);
    const GgxLobe lobe{r * r, std::clamp(cosView, 1e-4, 1.0)};
    const int n = options.samplesPerSide;
    CellFit fit;
    integrateMagnitude(lobe, 4 * n, &fit.cell.magnitude, &fit.cell.fresnel);
    const Mat3 frame = meanDirectionFrame(lobe, 2 * n);
    auto error = [&](const Shape& shape) {
        if (std::abs(shape[0]) < 1e-7 || std::abs(shape[1]) < 1e-7) return 1e300;
        return l1Distance(lobe, fit.cell.magnitude,
                          TransformedCosine::from(shapeMatrix(frame, shape)), n);
    };
    const Shape guess = start ? *start : Shape{lobe.alpha, lobe.alpha, 0.0, 0.0};
    // Steps of a tenth of the lobe's scale: the shapes of neighbouring cells differ by less.
    const double scaleOfLobe = std::max(std::abs(guess[0]), std::abs(guess[1]));
    fit.shape = minimise(
        error, guess, {0.1 * std::abs(guess[0]), 0.1 * std::abs(guess[1]), 0.1 * scaleOfLobe, 0.05},
        options.maxIterations);
    fit.shape[0] = std::abs(fit.shape[0]);
    fit.shape[1] = std::abs(fit.shape[1]);
    fit.error = error(fit.shape);
    const Mat3 mi = inverse(shapeMatrix(frame, fit.shape));
    const double s = 1.0 / mi[1][1];
    fit.cell.inverse00 = mi[0][0] * s;
    fit.cell.inverse02 = mi[0][2] * s;
    fit.cell.inverse20 = mi[2][0] * s;
    fit.cell.inverse22 = mi[2][2] * s;
    return fit;
}

double tableRoughness(int row, int size) {
    return kMinRoughness + (1.0 - kMinRoughness) * row / double(size - 1);
}

double tableCosView(int column, int size) {
    const double t = column / double(size - 1);
    return std::max(1e-4, 1.0 - t * t);
}

std::vector<CellFit> fitTable(int size, const FitOptions& options, int threads) {
    std::vector<CellFit> table(std::size_t(size) * size);
    std::atomic<int> nextRow{0};
    auto work = [&] {
        for (int row = nextRow++; row < size; row = nextRow++) {
            const Shape* start = nullptr;
            for (int column = 0; column < size; ++column) {
                CellFit& cell = table[std::size_t(row) * size + column];
                cell =
                    fitCell(tableRoughness(row, size), tableCosView(column, size), options, start);
                start = &cell.shape;
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::max(1, threads); ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    return table;
}

}  // namespace candela::ltc
