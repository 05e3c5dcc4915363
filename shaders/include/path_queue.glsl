// The current work queue of path ids (trace and shade visit only these) and
// both queues' counts; pt_shade declares the next queue, which it fills.
layout(binding = QL_BIND_QUEUE_IN, scalar) readonly buffer QueueIn { uint queueIn[]; };
layout(binding = QL_BIND_QUEUE_STATE, scalar) buffer Queues { QueueState queues[2]; };

const uint kNoPath = 0xffffffffu;

// Queue pc.bounce & 1 is the current one (pt_queue made it so); the dispatch
// covers its count rounded up to whole workgroups, hence the check.
uint queuedPath(uint slot) { return slot < queues[pc.bounce & 1u].count ? queueIn[slot] : kNoPath; }
