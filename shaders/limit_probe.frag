#version 460
// The limit probe's points: plain ink.
layout(location = 0) out vec4 out_color;

void main() { out_color = vec4(0.0, 0.0, 0.0, 1.0); }
