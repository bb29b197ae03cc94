// Embree 3 behind one header: only the plug-in's .cpp files include this, so no
// Embree type reaches a public header. A thin RAII layer: the device, a scene and a geometry
// own one Embree reference each and release it on destruction; every call that can fail is
// followed by check(), which turns the device's error code and the message its error callback
// recorded into a std::runtime_error (Embree's own C++ code must not be unwound through, so the
// callback records and the caller throws).
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "ray.hpp"

namespace sxk::bezier::embree {

// The last message Embree reported for a device; the callback may run on any thread.
struct ErrorLog {
    std::mutex mutex;
    std::string message;
};

inline const char* error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "no error";
        case RTC_ERROR_UNKNOWN:
            return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "unsupported CPU";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
    }
    return "unrecognised error";
}

// An Embree device (rtcNewDevice with the default configuration: Embree's own TBB threads build
// the BVH). Movable, not copyable; the device outlives every scene made from it because a
// scene keeps a shared reference to its Device.
class Device {
public:
    Device() : m_log(std::make_unique<ErrorLog>()) {
        m_device = rtcNewDevice(nullptr);
        if (m_device == nullptr)
            throw std::runtime_error(std::string("Embree: cannot create a device: ") +
                                     error_name(rtcGetDeviceError(nullptr)));
        rtcSetDeviceErrorFunction(m_device, &record, m_log.get());
    }
    ~Device() {
        if (m_device != nullptr)
            rtcReleaseDevice(m_device);
    }
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    RTCDevice get() const { return m_device; }

    // Throws when the last Embree call on this thread failed; `what` says which step it was.
    void check(const char* what) const {
        const RTCError code = rtcGetDeviceError(m_device);
        if (code == RTC_ERROR_NONE)
            return;
        std::string message;
        {
            std::lock_guard<std::mutex> lock(m_log->mutex);
            message = m_log->message;
        }
        throw std::runtime_error(std::string("Embree: ") + what + ": " + error_name(code) +
                                 (message.empty() ? "" : " (" + message + ")"));
    }

private:
    static void record(void* log, RTCError, const char* message) {
        auto* error_log = static_cast<ErrorLog*>(log);
        std::lock_guard<std::mutex> lock(error_log->mutex);
        error_log->message = message != nullptr ? message : "";
    }

    RTCDevice m_device = nullptr;
    std::unique_ptr<ErrorLog> m_log;  // stable address for the callback
};

// One Embree reference to a scene or a geometry, released on destruction.
template <typename Handle, void (*release)(Handle)>
class Owned {
public:
    Owned() = default;
    explicit Owned(Handle handle) : m_handle(handle) {}
    ~Owned() {
        if (m_handle != nullptr)
            release(m_handle);
    }
    Owned(Owned&& other) noexcept : m_handle(std::exchange(other.m_handle, nullptr)) {}
    Owned& operator=(Owned&& other) noexcept {
        if (this != &other) {
            if (m_handle != nullptr)
                release(m_handle);
            m_handle = std::exchange(other.m_handle, nullptr);
        }
        return *this;
    }
    Owned(const Owned&) = delete;
    Owned& operator=(const Owned&) = delete;

    Handle get() const { return m_handle; }

private:
    Handle m_handle = nullptr;
};

using SceneHandle = Owned<RTCScene, &rtcReleaseScene>;
using GeometryHandle = Owned<RTCGeometry, &rtcReleaseGeometry>;

// A scene for static geometry: robust traversal (no missed hits at shared edges, at a small
// cost) and a high-quality BVH, since our scenes are built once and traced many times.
inline SceneHandle new_scene(const Device& device) {
    SceneHandle scene(rtcNewScene(device.get()));
    device.check("rtcNewScene");
    rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene.get(), RTC_BUILD_QUALITY_HIGH);
    device.check("scene settings");
    return scene;
}

inline GeometryHandle new_geometry(const Device& device, RTCGeometryType type) {
    GeometryHandle geometry(rtcNewGeometry(device.get(), type));
    device.check("rtcNewGeometry");
    return geometry;
}

// Commits the geometry and attaches it to the scene (the scene keeps its own reference).
inline unsigned attach(const Device& device, const SceneHandle& scene,
                       const GeometryHandle& geometry) {
    rtcCommitGeometry(geometry.get());
    const unsigned id = rtcAttachGeometry(scene.get(), geometry.get());
    device.check("attaching a geometry");
    return id;
}

// Builds the BVH.
inline void commit(const Device& device, const SceneHandle& scene) {
    rtcCommitScene(scene.get());
    device.check("rtcCommitScene (BVH build)");
}

// A single ray as Embree takes it, no hit yet. Embree traces in float: the range is widened
// by one float step each way so that the float traversal never culls a hit inside the double
// range (the callbacks and the double refinement apply the exact range).
inline RTCRayHit ray_hit(const Ray& ray) {
    const auto widened_down = [](double t) {
        const float f = static_cast<float>(t);
        return static_cast<double>(f) > t
                   ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                   : f;
    };
    const auto widened_up = [](double t) {
        const float f = static_cast<float>(t);
        return static_cast<double>(f) < t
                   ? std::nextafter(f, std::numeric_limits<float>::infinity())
                   : f;
    };
    RTCRayHit query{};
    query.ray.org_x = static_cast<float>(ray.origin[0]);
    query.ray.org_y = static_cast<float>(ray.origin[1]);
    query.ray.org_z = static_cast<float>(ray.origin[2]);
    query.ray.dir_x = static_cast<float>(ray.direction[0]);
    query.ray.dir_y = static_cast<float>(ray.direction[1]);
    query.ray.dir_z = static_cast<float>(ray.direction[2]);
    query.ray.tnear = std::max(0.0f, widened_down(ray.t_near));
    query.ray.tfar = widened_up(ray.t_far);
    query.ray.mask = ~0u;
    query.ray.flags = 0;
    query.ray.time = 0;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.primID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return query;
}

}  // namespace sxk::bezier::embree
