#include "core/baselines/quaternion.h"

#include "core/geometry/angles.h"
#include "core/scheduling/plane_path.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace bladeaxis::baselines {

namespace {

using Quaternion = Eigen::Quaterniond;
constexpr double kPi = std::numbers::pi;

// Per input sample: the cutter-centre arc length, the original angle and the raw channel
// (absolute, unwrapped like the engine's angles).
struct Frame {
    std::vector<double> s, original, low, high;
    std::vector<bool> checked; // the sample is a layer sample of the reference (not a duplicate)
    double tilt = 0.0;
    int sign = 1;
};

Frame frameOf(const scheduling::ScheduleInput& input, const scheduling::ScheduleResult& ref) {
    const std::size_t n = input.centres.size();
    Frame f;
    f.tilt = ref.tiltB0;
    f.sign = ref.traversalSign;
    f.s.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
        f.s[i] = f.s[i - 1] + (input.centres[i] - input.centres[i - 1]).norm();
    }
    f.original = scheduling::absoluteAngles(ref, scheduling::Orientation::Original);
    f.low.assign(n, -1e300);
    f.high.assign(n, 1e300);
    f.checked.assign(n, false);
    for (const scheduling::LayerResult& layer : ref.layers) {
        for (std::size_t j = 0; j < layer.inputIndex.size(); ++j) {
            const std::size_t i = layer.inputIndex[j];
            f.low[i] = std::max(f.low[i], layer.junctionAngle + layer.thetaMin[j]);
            f.high[i] = std::min(f.high[i], layer.junctionAngle + layer.thetaMax[j]);
            f.checked[i] = true;
        }
    }
    return f;
}

// The tool frame Rx(-A) Ry(B0) with A = -sign * theta (spec §6.1, §7.2 (3)): R e_z is the axis.
Quaternion toolFrame(double theta, const Frame& f) {
    return Quaternion(Eigen::AngleAxisd(f.sign * theta, Vec3::UnitX())) *
           Quaternion(Eigen::AngleAxisd(f.tilt, Vec3::UnitY()));
}

Quaternion logOf(const Quaternion& q) {
    const double vectorNorm = q.vec().norm();
    const double angle = std::atan2(vectorNorm, q.w());
    const Vec3 v = vectorNorm > 1e-15 ? Vec3(q.vec() * (angle / vectorNorm)) : Vec3::Zero();
    return Quaternion(0.0, v.x(), v.y(), v.z());
}

Quaternion expOf(const Quaternion& q) {
    const double angle = q.vec().norm();
    const Vec3 v = angle > 1e-15 ? Vec3(q.vec() * (std::sin(angle) / angle)) : Vec3::Zero();
    return Quaternion(std::cos(angle), v.x(), v.y(), v.z());
}

Quaternion scaled(const Quaternion& q, double factor) {
    return Quaternion(q.w() * factor, q.x() * factor, q.y() * factor, q.z() * factor);
}

Quaternion added(const Quaternion& a, const Quaternion& b) {
    return Quaternion(a.w() + b.w(), a.x() + b.x(), a.y() + b.y(), a.z() + b.z());
}

// Shoemake's inner control point s_k = q_k exp(-(log(q_k^-1 q_k+1) + log(q_k^-1 q_k-1)) / 4).
Quaternion squadControl(const Quaternion& before, const Quaternion& q, const Quaternion& after) {
    const Quaternion inverse = q.conjugate();
    const Quaternion sum = added(logOf(inverse * after), logOf(inverse * before));
    return (q * expOf(scaled(sum, -0.25))).normalized();
}

class Interpolator {
  public:
    Interpolator(const Frame& frame, const QuaternionSettings& settings)
        : m_f(frame), m_settings(settings) {}

    // theta per sample of the open segment (a, b) of consecutive keys; `previous`/`next` are
    // the neighbouring keys (a or b themselves at the ends) for SQUAD's control points.
    void segment(std::size_t previous, std::size_t a, std::size_t b, std::size_t next,
                 const std::vector<double>& keyTheta, std::vector<double>& theta) const {
        const double ta = keyTheta[a], tb = keyTheta[b];
        const Quaternion qa = toolFrame(ta, m_f), qb = toolFrame(tb, m_f);
        const Quaternion sa = squadControl(toolFrame(keyTheta[previous], m_f), qa, qb);
        const Quaternion sb = squadControl(qa, qb, toolFrame(keyTheta[next], m_f));
        const double length = m_f.s[b] - m_f.s[a];
        // Unwrapped along the curve from the key, as the rotary axis follows it: SQUAD with few
        // keys can swing far from the straight interpolation, and unwrapping near that guess
        // would fold such a swing back into the channel.
        double along = ta;
        for (std::size_t i = a + 1; i < b; ++i) {
            const double u = length > 0.0 ? (m_f.s[i] - m_f.s[a]) / length : 0.0;
            const Vec3 axis = axisAt(qa, qb, sa, sb, ta, tb, u);
            along = geometry::unwrapNear(scheduling::planeAngle(axis, m_f.sign), along);
            theta[i] = along;
        }
    }

  private:
    Vec3 axisAt(const Quaternion& qa, const Quaternion& qb, const Quaternion& sa,
                const Quaternion& sb, double ta, double tb, double u) const {
        if (m_settings.mode == QuaternionMode::Vector) {
            const Vec3 va = scheduling::axisFromPlaneAngle(ta, m_f.tilt, m_f.sign);
            const Vec3 vb = scheduling::axisFromPlaneAngle(tb, m_f.tilt, m_f.sign);
            const double omega = std::acos(std::clamp(va.dot(vb), -1.0, 1.0));
            if (omega < 1e-12) {
                return va;
            }
            // Great-circle SLERP leaves the B0 cone; the caller re-projects it onto the cone.
            return (std::sin((1.0 - u) * omega) * va + std::sin(u * omega) * vb) / std::sin(omega);
        }
        Quaternion q = qa.slerp(u, qb);
        if (m_settings.interpolation == QuaternionInterpolation::Squad) {
            q = q.slerp(2.0 * u * (1.0 - u), sa.slerp(u, sb));
        }
        return q * Vec3::UnitZ();
    }

    const Frame& m_f;
    const QuaternionSettings& m_settings;
};

std::vector<std::size_t> initialKeys(const Frame& f, const scheduling::ScheduleResult& ref,
                                     int perLayer) {
    const std::size_t n = f.s.size();
    std::vector<std::size_t> keys{0, n - 1};
    keys.insert(keys.end(), ref.basePoints.begin(), ref.basePoints.end());
    for (const scheduling::LayerResult& layer : ref.layers) {
        const double s0 = f.s[layer.first], s1 = f.s[layer.last];
        std::size_t i = layer.first;
        for (int k = 1; k < perLayer; ++k) {
            const double target = s0 + (s1 - s0) * k / perLayer;
            while (i < layer.last && f.s[i] < target) {
                ++i;
            }
            keys.push_back(i);
        }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

double violation(const Frame& f, std::size_t i, double theta) {
    return f.checked[i] ? std::max(f.low[i] - theta, theta - f.high[i]) : 0.0;
}

class Repair {
  public:
    Repair(const Frame& frame, const QuaternionSettings& settings, std::vector<std::size_t> keys)
        : m_f(frame), m_settings(settings), m_interpolator(frame, settings),
          m_keys(std::move(keys)), m_keyTheta(frame.s.size(), 0.0), m_theta(frame.original) {
        for (std::size_t key : m_keys) {
            m_keyTheta[key] = frame.original[key];
        }
    }

    Status run(QuaternionResult& result) {
        if (auto status = interpolateAll(); !status) {
            return status;
        }
        for (int added = 0; added < m_settings.maxAdaptiveKeys; ++added) {
            const auto [worst, amount] = worstSample();
            if (amount <= 1e-9) {
                break;
            }
            insertKey(worst);
            if (auto status = interpolateAround(worst); !status) {
                return status;
            }
            ++result.adaptiveKeys;
        }
        result.worstViolation = std::max(0.0, worstSample().second);
        result.keys = m_keys;
        result.axes.reserve(m_theta.size());
        for (double theta : m_theta) {
            result.axes.push_back(scheduling::axisFromPlaneAngle(theta, m_f.tilt, m_f.sign));
        }
        return {};
    }

  private:
    // A key takes the original orientation clamped into the raw channel with the margin.
    void insertKey(std::size_t i) {
        const double low = m_f.low[i] + m_settings.margin, high = m_f.high[i] - m_settings.margin;
        m_keyTheta[i] = low <= high ? std::clamp(m_f.original[i], low, high) : 0.5 * (low + high);
        m_theta[i] = m_keyTheta[i];
        m_keys.insert(std::lower_bound(m_keys.begin(), m_keys.end(), i), i);
    }

    Status interpolateSegment(std::size_t k) {
        const std::size_t a = m_keys[k], b = m_keys[k + 1];
        if (std::abs(m_keyTheta[b] - m_keyTheta[a]) >= kPi) {
            return makeError(ErrorCode::Infeasible,
                             "quaternion keys at samples " + std::to_string(a) + " and " +
                                 std::to_string(b) +
                                 " are 180 deg or more apart: the shortest-arc interpolation "
                                 "would turn the wrong way (use more keys per layer)");
        }
        const std::size_t previous = m_keys[k == 0 ? 0 : k - 1];
        const std::size_t next = m_keys[std::min(k + 2, m_keys.size() - 1)];
        m_interpolator.segment(previous, a, b, next, m_keyTheta, m_theta);
        return {};
    }

    Status interpolateAll() {
        for (std::size_t k = 0; k + 1 < m_keys.size(); ++k) {
            if (auto status = interpolateSegment(k); !status) {
                return status;
            }
        }
        return {};
    }

    // A new key changes its two segments and, through SQUAD's control points, one more each side.
    Status interpolateAround(std::size_t key) {
        const auto at = static_cast<std::size_t>(
            std::lower_bound(m_keys.begin(), m_keys.end(), key) - m_keys.begin());
        const std::size_t from = at >= 2 ? at - 2 : 0;
        const std::size_t to = std::min(at + 2, m_keys.size() - 1);
        for (std::size_t k = from; k < to; ++k) {
            if (auto status = interpolateSegment(k); !status) {
                return status;
            }
        }
        return {};
    }

    std::pair<std::size_t, double> worstSample() const {
        std::pair<std::size_t, double> worst{0, -1e300};
        for (std::size_t i = 0; i < m_theta.size(); ++i) {
            const double amount = violation(m_f, i, m_theta[i]);
            if (amount > worst.second) {
                worst = {i, amount};
            }
        }
        return worst;
    }

    const Frame& m_f;
    const QuaternionSettings& m_settings;
    Interpolator m_interpolator;
    std::vector<std::size_t> m_keys;
    std::vector<double> m_keyTheta, m_theta;
};

} // namespace

std::string describe(const QuaternionSettings& settings) {
    return std::string(settings.mode == QuaternionMode::Vector                    ? "vector slerp"
                       : settings.interpolation == QuaternionInterpolation::Squad ? "squad"
                                                                                  : "slerp") +
           ", " + std::to_string(settings.keysPerLayer) + " keys/layer" +
           (settings.mode == QuaternionMode::Frame ? ", tool frame" : ", re-projected on B0");
}

std::vector<QuaternionSettings> fairnessSettings() {
    std::vector<QuaternionSettings> settings;
    for (int keys : {4, 8, 16, 32}) {
        for (auto interpolation :
             {QuaternionInterpolation::Slerp, QuaternionInterpolation::Squad}) {
            QuaternionSettings s;
            s.keysPerLayer = keys;
            s.interpolation = interpolation;
            settings.push_back(s);
        }
    }
    return settings;
}

Result<QuaternionResult> quaternionOrientations(const scheduling::ScheduleInput& input,
                                                const scheduling::ScheduleResult& reference,
                                                const QuaternionSettings& settings) {
    const std::size_t n = input.centres.size();
    if (n < 2 || reference.newAxes.size() != n || reference.layers.empty()) {
        return makeError(ErrorCode::InvalidArgument,
                         "the quaternion baseline needs the engine's schedule of the same input");
    }
    if (settings.keysPerLayer < 1 || !(settings.margin >= 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "quaternion settings: keys per layer >= 1 and margin >= 0 expected");
    }
    if (input.axes.size() != n) {
        return makeError(ErrorCode::InvalidArgument, "one tool axis per ball centre expected");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!input.centres[i].allFinite() || !input.axes[i].allFinite()) {
            return makeError(ErrorCode::Geometry,
                             "CL point " + std::to_string(i) + " is not finite (NaN or infinite)");
        }
    }
    const Frame frame = frameOf(input, reference);
    QuaternionResult result;
    result.settings = settings;
    Repair repair(frame, settings, initialKeys(frame, reference, settings.keysPerLayer));
    if (auto status = repair.run(result); !status) {
        return std::unexpected(status.error());
    }
    return result;
}

} // namespace bladeaxis::baselines
