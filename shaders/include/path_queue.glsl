// The current work queue of path ids, and the next one that shade fills.
layout(binding = QL_BIND_QUEUE_IN, scalar) readonly buffer QueueIn { uint queueIn[]; };
layout(binding = QL_BIND_QUEUE_STATE, scalar) buffer Queues { QueueState queues[2]; };

// pc.extend doubles as the index of the current queue in trace and shade.
uint queuedPath(uint slot) { return slot < queues[pc.bounce & 1u].count ? queueIn[slot] : 0xffffffffu; }
