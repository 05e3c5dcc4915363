// Learning Q from returns: the target of the Q entry a vertex's direction
// falls in is the radiance that direction actually brought back, everything
// the path gathered after the vertex (emission hits and NEE, MIS-weighted, at
// every later vertex) divided by the throughput up to the next vertex:
//   target_i = (L_end - L_i) / T_i.
// It is an unbiased estimate of the incident radiance Q stands for, and the
// points behind a door learn the light from NEE at once instead of waiting
// for rare scattered hits (D&K's TD target sees only those, issue 9).
//
// Each path keeps its last kReturnRecords vertices in a ring of path texels:
// the entry, the luminance of the radiance gathered before the direction's
// contributions (L_i) and of the throughput T_i. A record is written when the
// direction's ray has been traced (the next shade: L_i then includes the
// vertex's own NEE, which is not part of its return); it is flushed when the
// ring slot is reused (the return is truncated after kReturnRecords bounces)
// or when the path is done (pt_end). Luminances stand for the colours: the
// target is the throughput-weighted luminance of what came back.
// Flags bits kReturnRecordBit << slot mark the slots in use.
const uint kReturnRecordBit = 256u;

void flushReturnRecord(uint path, uint slot, float radianceNow) {
  vec4 r = pathTexel(path, kPathTexelReturnRecords + slot);
  recordQTarget(floatBitsToUint(r.x), max(radianceNow - r.y, 0.0) / r.z);
}

// At the shade of bounce >= 1: the direction of vertex bounce - 1 (st.prevEntry) is traced.
void openReturnRecord(inout PathState st, uint path, uint bounce) {
  uint slot = (bounce - 1u) % kReturnRecords;
  uint bit = kReturnRecordBit << slot;
  float radianceNow = luminance(st.radiance);
  if ((st.flags & bit) != 0u) flushReturnRecord(path, slot, radianceNow);
  float throughput = luminance(st.throughput);
  if (st.prevEntry == kNoCachePoint || !(throughput > 0.0)) {
    st.flags &= ~bit;
    return;
  }
  setPathTexel(path, kPathTexelReturnRecords + slot,
               vec4(uintBitsToFloat(st.prevEntry), radianceNow, throughput, 0.0));
  st.flags |= bit;
}

// When the path is done: every open record gets its return.
void flushReturnRecords(uint path, uint flags, float radianceEnd) {
  for (uint slot = 0u; slot < kReturnRecords; ++slot)
    if ((flags & (kReturnRecordBit << slot)) != 0u) flushReturnRecord(path, slot, radianceEnd);
}

bool learningFromReturns() {
  return kUseGuiding && kLearning && (guiding.flags & (kGuideLearn | kGuideLearnReturns)) ==
                            (kGuideLearn | kGuideLearnReturns);
}
