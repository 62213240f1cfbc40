#pragma once
// What the scheduling reads of its input: each sample's ball centre and tool axis, read where
// the caller keeps them (no copy of the input stands beside the scheduling's own arrays).

#include "core/geometry/vec.h"

#include <cstddef>
#include <optional>
#include <span>

namespace bladeaxis::scheduling {

// Vec3 values in the caller's memory, one every `stride` bytes: an array of them, or one member
// of an array of records (a toolpath's tips or axes), read in place.
class Vec3Run {
  public:
    Vec3Run() = default;
    explicit Vec3Run(std::span<const Vec3> values)
        : m_first(reinterpret_cast<const std::byte*>(values.data())), m_count(values.size()) {}
    template <class Record>
    Vec3Run(std::span<const Record> records, Vec3 Record::*member)
        : m_first(records.empty() ? nullptr
                                  : reinterpret_cast<const std::byte*>(&(records[0].*member))),
          m_stride(sizeof(Record)), m_count(records.size()) {}

    // The value itself, which lives at that address.
    const Vec3& operator[](std::size_t i) const {
        return *reinterpret_cast<const Vec3*>(m_first + i * m_stride);
    }
    std::size_t size() const { return m_count; }
    bool empty() const { return m_count == 0; }
    // The values as an array when they are one: the stages then read them through a span,
    // which the compiler vectorises (a strided read in the traversal sign's sum took three
    // times as long).
    std::optional<std::span<const Vec3>> contiguous() const {
        if (m_stride != sizeof(Vec3)) {
            return std::nullopt;
        }
        return std::span<const Vec3>(reinterpret_cast<const Vec3*>(m_first), m_count);
    }

  private:
    const std::byte* m_first = nullptr;
    std::size_t m_stride = sizeof(Vec3);
    std::size_t m_count = 0;
};

// The samples: the ball centres Q_i themselves, or the tool tips O_i, whose ball centre is
// O_i + R V_i / |V_i| (toolpath::ballCentre, the same expression), each with its tool axis V_i
// (normalised where it is read). A job reads its program's records (48 bytes per record it
// does not copy); the comparison and the tests give arrays.
struct ScheduleSamples {
    Vec3Run points; // centres, or tips when pointsAreTips
    Vec3Run axes;
    double toolRadius = 0.0; // R, mm
    bool pointsAreTips = false;

    static ScheduleSamples ofCentres(std::span<const Vec3> centres, std::span<const Vec3> axes,
                                     double toolRadius) {
        return {Vec3Run(centres), Vec3Run(axes), toolRadius, false};
    }

    std::size_t count() const { return axes.size(); }
    // The centres as an array, when they are given as one.
    std::optional<std::span<const Vec3>> contiguousCentres() const {
        return pointsAreTips ? std::nullopt : points.contiguous();
    }
    Vec3 centre(std::size_t i) const {
        return pointsAreTips ? Vec3(points[i] + toolRadius * axes[i].normalized()) : points[i];
    }
};

// A sample reader's centres as the stages read them, with operator[] and size().
class SampleCentres {
  public:
    explicit SampleCentres(const ScheduleSamples& samples) : m_samples(&samples) {}
    Vec3 operator[](std::size_t i) const { return m_samples->centre(i); }
    std::size_t size() const { return m_samples->points.size(); }
    bool empty() const { return size() == 0; }

  private:
    const ScheduleSamples* m_samples;
};

} // namespace bladeaxis::scheduling
