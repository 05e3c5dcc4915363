// A new path: one jittered camera ray through its pixel and a fresh state. pt_begin stores
// it; a fused camera-hit shade pass (kTraceInShade) starts its paths here instead of loading
// them, so the first bounce's state never goes through memory.
PathState cameraPath(uint path) {
  uvec2 pixel = uvec2(path % frame.resolution.x, path / frame.resolution.x);
  Rng rng = rngSeed(path, frame.frameIndex + pc.sampleIndex, frame.seed);
  vec2 ndc = (vec2(pixel) + rngNext2(rng)) / vec2(frame.resolution) * 2.0 - 1.0;
  GpuCamera cam = frame.camera;
  PathState s;
  s.origin = cam.position;
  s.dir = normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right -
                    ndc.y * cam.tanHalfFovY * cam.up);
  s.rng = rng.state;
  s.throughput = vec3(1.0);
  s.prevScatterPdf = 0.0;
  s.radiance = vec3(0.0);
  s.flags = kPathAlive;
  s.prevPoint = kNoCachePoint;
  s.prevEntry = kNoCachePoint;
  s.vertices = s.covered = s.shadowRays = 0u;
  s.rays = 1u;  // the camera ray (the shade pass counts the rays it makes)
  // A pixel's ray cone: no width at the eye, one pixel's angle of spread.
  // Rounded as the state stores it (half precision): a started and a loaded path are equal.
  s.coneWidth = 0.0;
  float spread = 2.0 * cam.tanHalfFovY / float(frame.resolution.y);
  s.coneSpread = unpackHalf2x16(packHalf2x16(vec2(spread, 0.0))).x;
  return s;
}
