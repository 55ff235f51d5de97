// Dispatches in rows of workgroups, along x up to GROUPS_PER_ROW and then along z, since a
// dispatch may have no more than 65,535 workgroups along x (GL's promised minimum) and a
// million lights need more. The CPU sizes some (render/programs/WorkgroupRows.h, whose
// kWorkgroupsPerRow is this number: every light of cluster_pairs.comp's counting run, every
// moving light of pose_lights.comp); the others are indirect dispatches over a list the GPU
// makes (the wide lights and the narrow lights with pairs of cluster_pairs.comp, the tiles with
// long lists of cluster_long_lists.comp), whose listing pass grows the counts.
const uint GROUPS_PER_ROW = 32768u;

// The workgroup of a dispatch listed that way (the first of z's row, the first after it...).
// The last row may run past the list's end: the shader compares it with the list's length.
uint listedGroup()
{
    return gl_WorkGroupID.z * GROUPS_PER_ROW + gl_WorkGroupID.x;
}

// What the item at `index` of a list adds to the dispatch over it, `itemsPerGroup` items a
// workgroup: (1, _) where it opens a workgroup of the first row, (_, 1) where it opens a row.
// The dispatch's x and z start at 0 and grow by these; its y is the caller's.
uvec2 listedDispatchGrowth(uint index, uint itemsPerGroup)
{
    if (index % itemsPerGroup != 0u)
        return uvec2(0u);
    uint group = index / itemsPerGroup;
    return uvec2(group < GROUPS_PER_ROW ? 1u : 0u, group % GROUPS_PER_ROW == 0u ? 1u : 0u);
}
