#version 460
// Wavefront pass 1: one camera ray per pixel (jittered), fresh path state.
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
layout(binding = QL_BIND_QUEUE_OUT, scalar) writeonly buffer QueueOut { uint queueOut[]; };

void main() {
  uint path = gl_GlobalInvocationID.x;
  if (path >= pc.pathCount) return;
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
  s.coneWidth = 0.0;
  s.coneSpread = 2.0 * cam.tanHalfFovY / float(frame.resolution.y);
  storePath(path, s);
  queueOut[path] = path;  // every path starts in queue 0 (its count is set by pt_queue)
}
