#include "anim/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace stipple::anim {

namespace {

void normalize4(double* q) {
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (length > 0.0)
        for (int i = 0; i < 4; ++i) q[i] /= length;
    else
        q[0] = q[1] = q[2] = 0.0, q[3] = 1.0;  // no rotation rather than NaN
}

}  // namespace

void slerp_short_arc(const double* a, const double* b, double s, double* out) {
    double qa[4], qb[4];
    for (int i = 0; i < 4; ++i) qa[i] = a[i], qb[i] = b[i];
    normalize4(qa);
    normalize4(qb);
    double d = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
    if (d < 0.0) {  // q and -q are the same rotation: take the one nearer a, the shorter way round
        for (double& c : qb) c = -c;
        d = -d;
    }
    double wa, wb;
    if (d > 1.0 - 1e-9) {  // nearly equal: sin(theta) vanishes, the chord is the arc
        wa = 1.0 - s;
        wb = s;
    } else {
        const double theta = std::acos(std::min(d, 1.0));
        const double sin_theta = std::sin(theta);
        wa = std::sin((1.0 - s) * theta) / sin_theta;
        wb = std::sin(s * theta) / sin_theta;
    }
    for (int i = 0; i < 4; ++i) out[i] = wa * qa[i] + wb * qb[i];
    normalize4(out);
}

void sample(const Sampler& sampler, double time, bool is_rotation, double* out) {
    const size_t c = sampler.components;
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    const size_t stride = cubic ? 3 * c : c;    // numbers per key
    const size_t value_at = cubic ? c : 0;      // the value sits between the two tangents
    const std::vector<float>& times = sampler.times;
    const float* values = sampler.values.data();
    auto copy_key = [&](size_t k) {
        for (size_t i = 0; i < c; ++i) out[i] = values[k * stride + value_at + i];
        if (is_rotation) normalize4(out);
    };
    // Key times are single precision, as the file stores them; the time asked is a double (1/24 s from a frame
    // count). One that rounds to a key's time is that key's: float(k / 24) lies above k / 24 for some k, and a
    // STEP animation sampled at its own key rate showed the key before (frames 1, 2, 4 and 8 of 10 keys at
    // 24 per second).
    if (const float rounded = static_cast<float>(time); double(rounded) != time &&
        std::binary_search(times.begin(), times.end(), rounded))
        time = rounded;
    if (time <= times.front()) return copy_key(0);
    if (time >= times.back()) return copy_key(times.size() - 1);
    // times[k] <= time < times[k + 1], so the interval has a positive length.
    const size_t k = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    const double t0 = times[k], t1 = times[k + 1], dt = t1 - t0;
    const double s = (time - t0) / dt;
    const float* v0 = values + k * stride + value_at;
    const float* v1 = values + (k + 1) * stride + value_at;
    switch (sampler.interpolation) {
        case Interpolation::Step: return copy_key(k);
        case Interpolation::Linear:
            if (is_rotation) {
                const double a[4] = {v0[0], v0[1], v0[2], v0[3]}, b[4] = {v1[0], v1[1], v1[2], v1[3]};
                return slerp_short_arc(a, b, s, out);
            }
            for (size_t i = 0; i < c; ++i) out[i] = (1.0 - s) * v0[i] + s * v1[i];
            return;
        case Interpolation::CubicSpline: {
            const float* out_tangent = values + k * stride + 2 * c;  // b_k
            const float* in_tangent = values + (k + 1) * stride;    // a_k+1
            const double s2 = s * s, s3 = s2 * s;
            const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
            for (size_t i = 0; i < c; ++i)
                out[i] = h00 * v0[i] + h10 * dt * out_tangent[i] + h01 * v1[i] + h11 * dt * in_tangent[i];
            if (is_rotation) normalize4(out);
            return;
        }
    }
}

}  // namespace stipple::anim
