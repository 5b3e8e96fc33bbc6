#include "glintlab/render/accel.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

struct Accelerator::Impl {
    const Scene* scene = nullptr;
    RTCDevice device = nullptr;
    RTCScene rtc = nullptr;
    std::vector<int> geom_to_shape;

    ~Impl() {
        if (rtc) rtcReleaseScene(rtc);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {

void check_device(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) fail("Embree error {} while {}", static_cast<int>(e), what);
}

SurfaceHit sphere_hit(const SphereGeometry& s, glm::vec3 p_raw) {
    SurfaceHit h;
    const glm::vec3 n = glm::normalize(p_raw - s.center);
    h.p = s.center + s.radius * n;  // re-project onto the sphere for accuracy
    h.ng = h.ns = n;
    // Object frame: p = r (sinθ cosφ, cosθ, sinθ sinφ), uv = (φ/2π, θ/π),
    // the same parameterization as make_sphere() so CPU and GPU agree.
    const glm::vec3 l = glm::transpose(s.rotation) * n;
    const float theta = std::acos(std::clamp(l.y, -1.0f, 1.0f));
    float phi = std::atan2(l.z, l.x);
    if (phi < 0.0f) phi += glm::two_pi<float>();
    h.uv = {phi * glm::one_over_two_pi<float>(), theta * glm::one_over_pi<float>()};
    const float st = std::sin(theta), ct = std::cos(theta);
    const float sp = std::sin(phi), cp = std::cos(phi);
    const glm::vec3 dpdphi = s.radius * glm::vec3(-st * sp, 0.0f, st * cp);
    const glm::vec3 dpdtheta = s.radius * glm::vec3(ct * cp, -st, ct * sp);
    h.dpdu = s.rotation * (glm::two_pi<float>() * dpdphi);
    h.dpdv = s.rotation * (glm::pi<float>() * dpdtheta);
    if (glm::dot(h.dpdu, h.dpdu) < 1e-12f * s.radius * s.radius) {
        // At the poles ∂p/∂φ vanishes: use any tangent orthogonal to dpdv.
        const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        h.dpdu = glm::normalize(glm::cross(n, a)) * s.radius * 1e-3f;
    }
    // n = (p − c)/r: the normal turns as the point moves.
    h.dndu = h.dpdu / s.radius;
    h.dndv = h.dpdv / s.radius;
    h.has_uv = true;
    return h;
}

SurfaceHit triangle_hit(const TriangleMesh& m, unsigned prim, float bu, float bv) {
    SurfaceHit h;
    const glm::uvec3 tri = m.triangles[prim];
    const glm::vec3 p0 = m.positions[tri.x], p1 = m.positions[tri.y], p2 = m.positions[tri.z];
    const float b0 = 1.0f - bu - bv;
    h.p = b0 * p0 + bu * p1 + bv * p2;
    h.ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    glm::vec2 uv0(0.0f, 0.0f), uv1(1.0f, 0.0f), uv2(1.0f, 1.0f);
    if (m.has_uvs()) {
        uv0 = m.uvs[tri.x], uv1 = m.uvs[tri.y], uv2 = m.uvs[tri.z];
        h.has_uv = true;
    }
    h.uv = b0 * uv0 + bu * uv1 + bv * uv2;
    // ∂p/∂u, ∂p/∂v from the triangle's uv mapping (pbrt-v4 Triangle).
    const glm::vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    const glm::vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    const float det = duv02.x * duv12.y - duv02.y * duv12.x;
    bool degenerate = std::abs(det) < 1e-12f;
    if (!degenerate) {
        const float inv = 1.0f / det;
        h.dpdu = (duv12.y * dp02 - duv02.y * dp12) * inv;
        h.dpdv = (duv02.x * dp12 - duv12.x * dp02) * inv;
        degenerate =
            glm::length(glm::cross(h.dpdu, h.dpdv)) == 0.0f ||
            !std::isfinite(h.dpdu.x + h.dpdu.y + h.dpdu.z + h.dpdv.x + h.dpdv.y + h.dpdv.z);
    }
    if (degenerate) {
        const glm::vec3 a = std::abs(h.ng.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        h.dpdu = glm::normalize(glm::cross(h.ng, a));
        h.dpdv = glm::cross(h.ng, h.dpdu);
    }
    if (!m.tangents.empty()) {
        const glm::vec4 t0 = m.tangents[tri.x], t1 = m.tangents[tri.y], t2 = m.tangents[tri.z];
        h.tangent = glm::vec4(glm::vec3(b0 * t0 + bu * t1 + bv * t2),
                              b0 * t0.w + bu * t1.w + bv * t2.w < 0.0f ? -1.0f : 1.0f);
    }
    if (m.has_normals()) {
        const glm::vec3 n0 = m.normals[tri.x], n1 = m.normals[tri.y], n2 = m.normals[tri.z];
        const glm::vec3 n = b0 * n0 + bu * n1 + bv * n2;
        const float len = glm::length(n);
        h.ns = len > 0.0f ? n / len : h.ng;
        // The geometric normal follows the shading normal's side.
        if (glm::dot(h.ng, h.ns) < 0.0f) h.ng = -h.ng;
        if (len > 0.0f && !degenerate) {
            // ∂n/∂(u, v) of the interpolated normal by the same uv solve as
            // ∂p/∂(u, v); the unit normal's derivative is its part
            // orthogonal to ns, divided by |n|.
            const float inv = 1.0f / det;
            const glm::vec3 dn02 = n0 - n2, dn12 = n1 - n2;
            const glm::vec3 dndu = (duv12.y * dn02 - duv02.y * dn12) * inv;
            const glm::vec3 dndv = (duv02.x * dn12 - duv12.x * dn02) * inv;
            h.dndu = (dndu - h.ns * glm::dot(h.ns, dndu)) / len;
            h.dndv = (dndv - h.ns * glm::dot(h.ns, dndv)) / len;
            if (!std::isfinite(h.dndu.x + h.dndu.y + h.dndu.z + h.dndv.x + h.dndv.y + h.dndv.z))
                h.dndu = h.dndv = glm::vec3(0.0f);
        }
    } else {
        h.ns = h.ng;
    }
    return h;
}

}  // namespace

Accelerator::Accelerator(const Scene& scene) : impl_(std::make_unique<Impl>()) {
    impl_->scene = &scene;
    // The default configuration: with the TBB tasking system Embree keeps a
    // process-wide tbb::global_control at the device's thread count, so the
    // "threads=1" this had since the first renderer capped every TBB loop of
    // the process (the renderer's tiles, not only Embree's BVH build) at one
    // thread: CPU renders ran on one core whatever --threads said.
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device)
        fail("cannot create an Embree device (error {})",
             static_cast<int>(rtcGetDeviceError(nullptr)));
    impl_->rtc = rtcNewScene(impl_->device);
    rtcSetSceneFlags(impl_->rtc, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl_->rtc, RTC_BUILD_QUALITY_HIGH);
    for (size_t i = 0; i < scene.shapes.size(); ++i) {
        const Shape& shape = scene.shapes[i];
        RTCGeometry g = nullptr;
        if (const auto* s = std::get_if<SphereGeometry>(&shape.geometry)) {
            g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
            v[0] = s->center.x, v[1] = s->center.y, v[2] = s->center.z, v[3] = s->radius;
        } else {
            const auto& m = std::get<TriangleMesh>(shape.geometry);
            g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        3 * sizeof(float), m.positions.size()));
            for (size_t k = 0; k < m.positions.size(); ++k) {
                v[3 * k] = m.positions[k].x;
                v[3 * k + 1] = m.positions[k].y;
                v[3 * k + 2] = m.positions[k].z;
            }
            auto* idx = static_cast<unsigned*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                        3 * sizeof(unsigned), m.triangles.size()));
            for (size_t k = 0; k < m.triangles.size(); ++k) {
                idx[3 * k] = m.triangles[k].x;
                idx[3 * k + 1] = m.triangles[k].y;
                idx[3 * k + 2] = m.triangles[k].z;
            }
        }
        check_device(impl_->device, "creating geometry");
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(impl_->rtc, g);
        rtcReleaseGeometry(g);
        if (impl_->geom_to_shape.size() <= id) impl_->geom_to_shape.resize(id + 1, -1);
        impl_->geom_to_shape[id] = static_cast<int>(i);
    }
    rtcCommitScene(impl_->rtc);
    check_device(impl_->device, "building the acceleration structure");
}

Accelerator::~Accelerator() = default;

std::optional<SurfaceHit> Accelerator::intersect(const Ray& ray, float t_max) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = ray.o.x, rh.ray.org_y = ray.o.y, rh.ray.org_z = ray.o.z;
    rh.ray.dir_x = ray.d.x, rh.ray.dir_y = ray.d.y, rh.ray.dir_z = ray.d.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = t_max;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->rtc, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const int shape_index = impl_->geom_to_shape[rh.hit.geomID];
    const Shape& shape = impl_->scene->shapes[shape_index];
    SurfaceHit h;
    if (const auto* s = std::get_if<SphereGeometry>(&shape.geometry)) {
        h = sphere_hit(*s, ray.o + rh.ray.tfar * ray.d);
    } else {
        h = triangle_hit(std::get<TriangleMesh>(shape.geometry), rh.hit.primID, rh.hit.u, rh.hit.v);
    }
    h.t = rh.ray.tfar;
    h.shape = shape_index;
    return h;
}

bool Accelerator::occluded(glm::vec3 origin, glm::vec3 dir, float t_max) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r{};
    r.org_x = origin.x, r.org_y = origin.y, r.org_z = origin.z;
    r.dir_x = dir.x, r.dir_y = dir.y, r.dir_z = dir.z;
    r.tnear = 0.0f;
    r.tfar = t_max;
    r.mask = 0xFFFFFFFFu;
    rtcOccluded1(impl_->rtc, &context, &r);
    return r.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}

glm::vec3 offset_ray_origin(const SurfaceHit& hit, glm::vec3 dir) {
    const float scale =
        1e-4f * std::max(1.0f, std::max({std::abs(hit.p.x), std::abs(hit.p.y), std::abs(hit.p.z)}));
    const glm::vec3 n = glm::dot(dir, hit.ng) >= 0.0f ? hit.ng : -hit.ng;
    return hit.p + scale * n;
}

}  // namespace glintlab
