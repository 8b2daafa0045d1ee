// Work of more workgroups than a dispatch may have along x (maxComputeWorkGroupCount[0]: 65535 on
// lavapipe and on many GPUs, a model of 4.2M polygons at 64 a group) is spread over rows along y. The host
// splits its direct dispatches (gpu::dispatch_groups), the passes that append to a list grow the list's
// indirect dispatch the same way (GROW_DISPATCH), and every pass so dispatched numbers its invocations with
// linear_invocation(); those past the work return, as the last group's always did.
#ifndef STIPPLE_DISPATCH_H
#define STIPPLE_DISPATCH_H

// The widest row: the device's maxComputeWorkGroupCount[0] (gpu::Context::max_groups_x), set for every
// compute pipeline by gpu::create_compute_pipeline.
layout(constant_id = kSpecMaxGroupsX) const uint kMaxGroupsX = 65535u;

// A macro, not a function: gl_WorkGroupSize is the shader's local size only after its layout(local_size_x)
// declaration, which follows the includes (a function here read (1, 1, 1) and every invocation overlapped).
#define linear_invocation() \
    ((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x)

// A list's VkDispatchIndirectCommand (its groups_x, groups_y) once it holds `items` entries, in groups of
// kDensityWorkgroupSize: rows of at most kMaxGroupsX. Entries are claimed by atomic adds that tile 0, 1,
// 2, ..., so the largest end any claim reaches is the list's length, and atomicMax makes the command
// follow it whatever order the claims land in. The list is cleared to (0, 1, 1).
#define GROW_DISPATCH(list, items)                                                           \
    {                                                                                        \
        uint groups_ = ((items) + kDensityWorkgroupSize - 1u) / kDensityWorkgroupSize;        \
        atomicMax(list.groups_x, min(groups_, kMaxGroupsX));                                 \
        if (groups_ > kMaxGroupsX) atomicMax(list.groups_y, (groups_ + kMaxGroupsX - 1u) / kMaxGroupsX); \
    }

#endif
