#version 460
// The bench's limit probe (issue 17): as many points as the vertex path draws candidates, with no
// inputs but the vertex index. Culled ones go beyond the far plane (as stipple.vert culls), drawn
// ones are points of the stipples' size at hashed places in a square the size of the model's
// footprint; the drawn ones are spread evenly among the culled, as survivors are among a polygon's
// candidates.
layout(push_constant) uniform Probe {
    uint total;   // points in the draw
    uint drawn;   // of which drawn
    float side;   // the footprint square's side, pixels
    float width, height;
    float point_size;  // the stipples' as drawn (drawn_point_size): a rasteriser may set up wider points otherwise
} probe;

uint hash(uint x) {  // a 32-bit integer mix (lowbias32)
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

void main() {
    uint i = uint(gl_VertexIndex);
    float rate = float(probe.drawn) / float(probe.total);
    gl_PointSize = probe.point_size;
    if (uint(float(i + 1u) * rate) == uint(float(i) * rate)) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // z > w: beyond the far plane, clipped
        return;
    }
    uint h = hash(i);
    vec2 unit = vec2(float(h & 0xFFFFu), float(h >> 16u)) / 65535.0;
    vec2 pixel = 0.5 * vec2(probe.width, probe.height) + (unit - 0.5) * probe.side;
    gl_Position = vec4(2.0 * pixel / vec2(probe.width, probe.height) - 1.0, 0.5, 1.0);
}
