#include "anim/deform_cpu.hpp"

#include "core/parallel.hpp"

namespace stipple::anim {

glm::dmat4 blend_matrix(const AnimatedModel& model, const Pose& pose, size_t v) {
    const Influences& inf = model.influences[v];
    glm::dmat4 m(0.0);
    for (uint32_t i = 0; i < kMaxInfluences; ++i)
        if (inf.weight[i] != 0.0f) m += double(inf.weight[i]) * glm::dmat4(pose.palette[inf.slot[i]]);
    return m;
}

void deform_vertex(const AnimatedModel& model, const Pose& pose, size_t v, glm::dvec3& position, glm::dvec3& normal) {
    glm::dvec3 p(model.bind_positions[v]);
    glm::dvec3 n(model.bind_normals[v]);
    const MorphRef& morph = model.morph_refs[v];
    for (uint32_t k = 0; k < morph.count; ++k) {
        const double w = pose.morph_weights[morph.first_weight + k];
        const MorphDelta& d = model.morph_deltas[morph.first_delta + k];
        p += w * glm::dvec3(d.position);
        n += w * glm::dvec3(d.normal);
    }
    const glm::dmat4 m = blend_matrix(model, pose, v);
    position = glm::dvec3(m * glm::dvec4(p, 1.0));
    // The inverse transpose up to a positive factor: cofactors, with det's sign (a mirroring blend
    // keeps normals pointing out of the faces, which loading re-wound for the rest pose's mirroring),
    // which also works for a singular blend.
    const glm::dvec3 c0(m[0]), c1(m[1]), c2(m[2]);
    const glm::dvec3 x = glm::cross(c1, c2);
    const double det_sign = glm::dot(c0, x) < 0.0 ? -1.0 : 1.0;
    const glm::dvec3 transformed = glm::dmat3(x, glm::cross(c2, c0), glm::cross(c0, c1)) * n;
    const double length = glm::length(transformed);
    normal = length > 0.0 ? transformed * (det_sign / length) : glm::dvec3(0.0, 0.0, 1.0);
}

void deform_cpu(const AnimatedModel& model, const Pose& pose, DeformedGeometry& out) {
    const size_t n = model.vertex_count();
    out.positions.resize(n);
    out.normals.resize(n);
    parallel_for(n, 4096, [&](size_t v) {
        glm::dvec3 p, normal;
        deform_vertex(model, pose, v, p, normal);
        out.positions[v] = glm::vec3(p);
        out.normals[v] = glm::vec3(normal);
    });
}

DeformedGeometry deform_cpu(const AnimatedModel& model, const Pose& pose) {
    DeformedGeometry out;
    deform_cpu(model, pose, out);
    return out;
}

}  // namespace stipple::anim
