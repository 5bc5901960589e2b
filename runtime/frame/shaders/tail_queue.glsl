// The tail queue of one view: pixels whose full-resolution march did not finish within
// FG_TAIL_AFTER steps, to be finished by the tail pass in compact workgroups instead of keeping
// whole groups waiting on a few slow pixels. The first three words are the tail pass's indirect
// dispatch size: every 64th item adds a group.
struct FgTailItem {
    uint pixel;       // x | y << 16
    float t;
    float closest;
    uint steps;       // steps taken so far
};
layout(set = 0, binding = 7, std430) buffer FgTail {
    uint groups[3];
    uint count;
    FgTailItem items[];
} fg_tail;

void fg_tail_append(ivec2 pixel, float t, float closest, uint steps)
{
    uint index = atomicAdd(fg_tail.count, 1u);
    if (index >= uint(fg_tail.items.length())) return;   // cannot happen: the queue holds every pixel
    if (index % 64u == 0u) atomicAdd(fg_tail.groups[0], 1u);
    fg_tail.items[index] = FgTailItem(uint(pixel.x) | (uint(pixel.y) << 16), t, closest, steps);
}
