// Scene and frame features the path tracing passes are specialized on. On
// lavapipe both sides of every branch execute (masked SIMD), so code for a
// feature the frame does not use must not be in the pipeline at all: a
// specialization constant set to false removes it at pipeline creation.
layout(constant_id = 3) const bool kUseTextures = true;
layout(constant_id = 4) const bool kUseGuiding = true;
layout(constant_id = 5) const bool kUseLightLearning = true;
layout(constant_id = 6) const bool kUseNonTriangleLights = true;  // punctual, directional, sky
