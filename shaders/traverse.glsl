// Two-level BVH traversal: iterative, with a fixed stack (no recursion in GLSL).
// Nodes hold both children's boxes and stack entries (48 bytes, 3 texels; 64 bytes where packing
// would loosen the boxes too much: device_host.h, GpuBvhNode), so each step decides both children
// from one contiguous fetch. Each pass of the main loop walks inner nodes (an inner loop, one
// node's two children per pass) until the lane holds something else, then handles it: intersects
// a bottom-level leaf's primitives (a second inner loop: "while-while", Aila & Laine 2009) or
// enters an instance. Nothing marks the way back to the top level: the walk tests each node with
// the ray of its level, told by the node's index (the top level and the inlined world group: the
// world ray). A far leaf is pushed like a node, as a packed entry (device_host.h, ENTRY_LEAF_BIT).
// Why this shape: lavapipe (Mesa 22.3) runs every statement of a loop body for all 8 lanes, masked,
// whatever the branch conditions, and a loop body runs at least once (host/gpu/README.md, fact 2).
// So the walk, the loop that runs most, holds only what every pass needs (each step below measured
// faster in alternating runs: docs/lab/2026-12-02-gpu-rays-and-scenes.md):
//  - the leaf's primitive tests are a loop of their own, run once per leaf round. Inside the walk's
//    pass they cost one full primitive test per pass even when no lane had a leaf;
//  - instance steps moved out too;
//  - the stack's top REG_STACK entries live in registers, shifted on push and pop. A private array
//    indexed per lane is a scalar load or masked store per lane (with a branch per lane that
//    mispredicts); the walk touched it twice per pass. Now only the main loop does: it stores the
//    entry that a push with full registers shifted out, and refills when a pop finds them empty.
//    A CPU simulation put the extra leaf rounds from spills and refills at 12-16% with 4
//    registers; 6 or 8 measured no better.
// Letting a lane that holds a leaf walk on while the others look for theirs (speculative,
// subgroupAll to end the walk, or a lane stopping at its second leaf) was slower, and so was a
// 4-wide node (docs/BENCHMARKS.md, "Tried and not kept").
#include "hit_order.h"  // which of two candidates at (nearly) one distance wins

#ifndef VKRT_TRAVERSE_GLSL
#define VKRT_TRAVERSE_GLSL

struct Hit {
    float t;
    uint instance;  // index into the instance table
    uint prim;      // index into the primitive array
    vec2 bary;      // triangle: barycentric weights of v1 and v2
};

// Stack entries: an inner node (its first texel), a bottom-level leaf, an instance to enter (device_host.h:
// the host writes these into the nodes), or the kernel's own marker for a refill.
const uint ENTRY_REFILL = 0xfffffffdu;  // a pop found the registers empty: the next round takes the array's top
const uint REG_STACK = 4u;  // stack entries kept in registers

vec3 texelFloats(uvec4 t) { return uintBitsToFloat(t.xyz); }

// min and max as selects: GLSL's min/max must return the other operand for a NaN, which lavapipe
// spells as three instructions (min, unordered compare, blend); the slab distances are never NaN
// (box bounds finite, invDir never 0: safeInverse), and a select of a compare is one vminps/vmaxps
// (host/gpu/README.md, fact 5).
float fmin(float a, float b) { return a < b ? a : b; }
float fmax(float a, float b) { return a > b ? a : b; }
vec3 vmin(vec3 a, vec3 b) { return vec3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
vec3 vmax(vec3 a, vec3 b) { return vec3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }

// Slab test of one child box, conservative by 1 + 2*gamma(3) on the exit distance (Ize 2013,
// "Robust BVH Ray Traversal") so rounding can never cull a box the ray truly enters.
bool hitsBox(vec3 origin, vec3 invDir, vec3 lo, vec3 hi, float tBest, out float tNear) {
    vec3 t0 = (lo - origin) * invDir;
    vec3 t1 = (hi - origin) * invDir;
    vec3 tMin = vmin(t0, t1);
    vec3 tMax = vmax(t0, t1);
    tNear = fmax(fmax(fmax(tMin.x, tMin.y), tMin.z), 0.0);
    float tFar = fmin(fmin(fmin(tMax.x, tMax.y), tMax.z), tBest) * 1.00000036;
    return tNear <= tFar;
}

// The primitive whose first texel is `base` (prim * PRIM_TEXELS: the caller steps it, so the leaf
// loop's fetch waits on no multiply).
bool intersectPrimitive(TraceRay ray, int base, float tBest, out float tHit, out vec2 bary) {
    tHit = 0.0;
    bary = vec2(0.0);
    uvec4 a = imageLoad(primitives, base);
    uint kind = primitiveKind(a);
    if (HAS_TRIANGLES && kind == PRIM_KIND_TRIANGLE) {
        vec3 v1 = texelFloats(imageLoad(primitives, base + 1));
        vec3 v2 = texelFloats(imageLoad(primitives, base + 2));
        return intersectTriangle(ray, texelFloats(a), v1, v2, tBest, tHit, bary);
    }
    if (HAS_SPHERES && kind == PRIM_KIND_SPHERE) {
        float radius = uintBitsToFloat(imageLoad(primitives, base + 1).x);
        return intersectSphere(ray, texelFloats(a), radius, tBest, tHit);
    }
    if (HAS_BOXES && kind == PRIM_KIND_BOX) {
        vec3 hi = texelFloats(imageLoad(primitives, base + 1));
        return intersectBox(ray, texelFloats(a), hi, tBest, tHit);
    }
    return false;
}

// The world ray in an instance's object space (direction not renormalised: t is unchanged).
TraceRay rayIntoInstance(vec3 origin, vec3 dir, uint instance) {
    vec4 r0 = instanceRow(instance, 0u);  // worldToObject
    vec4 r1 = instanceRow(instance, 1u);
    vec4 r2 = instanceRow(instance, 2u);
    uint motion = instanceMotion(instance);
    if (motion != MOTION_NONE) {  // a moving instance: its inverse at the sample's time
        Instance posed = posedInstance(instance, motion);
        r0 = posed.worldToObject[0];
        r1 = posed.worldToObject[1];
        r2 = posed.worldToObject[2];
    }
    vec3 o = vec3(dot(r0.xyz, origin) + r0.w, dot(r1.xyz, origin) + r1.w, dot(r2.xyz, origin) + r2.w);
    vec3 d = vec3(dot(r0.xyz, dir), dot(r1.xyz, dir), dot(r2.xyz, dir));
    return makeTraceRay(o, d);
}

// An inner node's first texel (leaf entries, instance entries and the kernel's marker have bit 30 or 31 set).
bool isNodeEntry(uint e) { return (e & (ENTRY_INSTANCE_BIT | ENTRY_LEAF_BIT)) == 0u; }
bool isLeafEntry(uint e) { return (e & (ENTRY_INSTANCE_BIT | ENTRY_LEAF_BIT)) == ENTRY_LEAF_BIT; }
// An instance to enter (top bit; ENTRY_REFILL and ENTRY_NONE have it too).
bool isInstanceEntry(uint e) { return (e & ENTRY_INSTANCE_BIT) != 0u && e < ENTRY_REFILL; }

// The stack entry of the root node `index`: its first texel, like the entries the host writes
// into the nodes (node_packing.h), so that the walk's fetch needs no multiply.
uint rootEntry(uint index) { return index * (PACKED_NODES ? GPU_NODE_TEXELS : GPU_EXACT_NODE_TEXELS); }

// Child K's stack entry, carried in the low bits of its box floats (device_host.h, GpuBvhNode).
uint nodeChildEntry(uvec4 xy, uvec2 z) {
    const uint xyMask = (1u << NODE_ENTRY_XY_BITS) - 1u;
    return (xy.x & xyMask) | ((xy.y & xyMask) << NODE_ENTRY_XY_BITS) | ((xy.z & xyMask) << (2u * NODE_ENTRY_XY_BITS)) |
           ((xy.w & xyMask) << (3u * NODE_ENTRY_XY_BITS)) | ((z.x & ((1u << NODE_ENTRY_Z_BITS) - 1u)) << (4u * NODE_ENTRY_XY_BITS)) |
           (z.y << (4u * NODE_ENTRY_XY_BITS + NODE_ENTRY_Z_BITS));
}

// The stack's register part, r0 on top (REG_STACK entries; see the header): a push shifts the
// entries down (r3 falls off: the caller saves it first if it was held), a pop shifts them up.
void shiftIn(inout uint r0, inout uint r1, inout uint r2, inout uint r3, uint value) {
    r3 = r2;
    r2 = r1;
    r1 = r0;
    r0 = value;
}
uint shiftOut(inout uint r0, inout uint r1, inout uint r2, uint r3) {
    uint top = r0;
    r0 = r1;
    r1 = r2;
    r2 = r3;
    return top;
}

// The next entry: the top register, else ENTRY_REFILL. The caller tells a refill (the next round
// takes the array's top) from the end of the ray (the array is empty too) after the walk, so the
// walk keeps neither the array's depth nor a finished flag live: a shorter pass, with fewer
// stack-frame accesses (profile_jit.py; docs/lab/2026-12-02-lavapipe-kernel.md).
void popEntry(inout uint entry, inout uint held, inout uint r0, inout uint r1, inout uint r2, uint r3) {
    if (held > 0u) {
        entry = shiftOut(r0, r1, r2, r3);
        --held;
    } else {
        entry = ENTRY_REFILL;
    }
}

bool g_rayStackOverflow = false;  // a traversal stack overflowed (STATUS_RAY_STACK_OVERFLOW)

// The invocation's failures as STATUS_* bits: the entry point reports them once (an atomic where
// they arise would be a per-lane loop on lavapipe; see the end of traceScene).
uint failureFlags() {
    return (g_budgetExceeded ? STATUS_LOOP_BUDGET_EXCEEDED : 0u) |
           (g_loopCutOff && !g_budgetExceeded ? STATUS_LOOP_CUT_OFF : 0u) |
           (g_rayStackOverflow ? STATUS_RAY_STACK_OVERFLOW : 0u);
}

// Closest hit (anyHit = false) or any hit (shadow rays) with 0 < t < tMax.
const float FLT_MAX = 3.402823466e+38;  // tMax of a ray with no end

bool traceScene(vec3 origin, vec3 dir, float tMax, bool anyHit, out Hit hit) {
    hit.t = tMax;
    hit.instance = 0u;
    hit.prim = 0u;
    hit.bary = vec2(0.0);
    bool found = false;
    // Boxes and primitives are tested against tLimit: the end of the best hit's bucket
    // (hit_order.h), where a farther candidate may still win on its indices.
    float tLimit = tMax;

    TraceRay worldRay = makeTraceRay(origin, dir);
    TraceRay ray = worldRay;
    // The stack: its top REG_STACK entries in registers (r0 = top), the rest in a private array
    // that only the main loop touches (see the header).
    uint stack[TRAVERSAL_STACK_SIZE];
    uint sp = 0u;  // entries in the array
    uint r0 = ENTRY_NONE, r1 = ENTRY_NONE, r2 = ENTRY_NONE, r3 = ENTRY_NONE;
    uint held = 0u;  // entries in registers
    bool spilling = false;
    uint spillEntry = ENTRY_NONE;
    uint instance = 0u;
    uint entry = rootEntry(HAS_INSTANCES ? frameTopLevelRoot() : instanceRootNode(instanceInfo(0u)));
    // The top level's nodes come last in the node array, from its root on (bvh.h, SceneBvh::nodes;
    // the host checks it: node_packing.h), so an entry at or past the root's is a top-level node.
    // The world group's nodes (frame.world, node_packing.h InlinedWorld: the loose shapes of
    // instance 0, whose transform is the identity) are walked as part of the top level, with the
    // world ray, and its leaves are tested with it: no instance step to reach them.
    uint topLevelStart = HAS_INSTANCES ? entry : 0u;
    uvec4 world = frame.world;
    bool finished = false;
    bool overflow = false;

    while (true) {
        if (!chargeLoop()) break;
        // 0. The array's only load: a refill (the walk or the last pop found the registers empty)
        // takes its top as the entry; otherwise an empty register stack tops up from it, so the
        // walk's next pop does not end the walk for a refill round (each round pays a primitive-test
        // pass; docs/lab/2026-12-02-gpu-rays-and-scenes.md). One load site and one store site
        // (step 3): each is a per-lane loop that every lane runs on every round (host/gpu/README.md,
        // fact 3).
        bool refill = entry == ENTRY_REFILL;
        if ((refill || held == 0u) && sp > 0u) {
            --sp;
            uint top = stack[sp];
            if (refill) {
                entry = top;
            } else {
                r0 = top;
                held = 1u;
            }
        }
        // 1. Walk the tree until this lane holds a leaf, an instance to enter, or needs the array:
        // to spill a register entry, or because its registers are empty (ENTRY_REFILL: a refill
        // from the array, or the end of the ray when the array is empty too, told right after).
        while (!spilling && isNodeEntry(entry)) {
            if (!chargeLoop()) break;
            int base = int(entry);  // a node's entry is its first texel (node_packing.h)
            // A top-level node (or the inlined world group's) tests the world ray, a bottom-level
            // one the instance's (see the instance step below).
            bool topLevelNode = HAS_INSTANCES && (entry >= topLevelStart || worldHoldsNodeEntry(world, entry));
            vec3 boxOrigin = topLevelNode ? worldRay.origin : ray.origin;
            vec3 boxInvDir = topLevelNode ? worldRay.invDir : ray.invDir;
            uvec4 xy0 = imageLoad(bvhNodes, base);
            uvec4 xy1 = imageLoad(bvhNodes, base + 1);
            uvec4 z01 = imageLoad(bvhNodes, base + 2);
            vec4 fxy0 = uintBitsToFloat(xy0);
            vec4 fxy1 = uintBitsToFloat(xy1);
            vec4 fz = uintBitsToFloat(z01);
            float tNear0, tNear1;
            bool box0 = hitsBox(boxOrigin, boxInvDir, vec3(fxy0.x, fxy0.z, fz.x), vec3(fxy0.y, fxy0.w, fz.y), tLimit, tNear0);
            bool box1 = hitsBox(boxOrigin, boxInvDir, vec3(fxy1.x, fxy1.z, fz.z), vec3(fxy1.y, fxy1.w, fz.w), tLimit, tNear1);
            uint next0, next1;
            if (PACKED_NODES) {
                next0 = nodeChildEntry(xy0, z01.xy);
                next1 = nodeChildEntry(xy1, z01.zw);
            } else {
                uvec2 entries = imageLoad(bvhNodes, base + 3).xy;
                next0 = entries.x;
                next1 = entries.y;
            }
            bool hit0 = box0 && next0 != ENTRY_NONE;
            bool hit1 = box1 && next1 != ENTRY_NONE;
            bool nearFirst = !(hit0 && hit1 && tNear1 < tNear0);
            bool push = hit0 && hit1;
            uint pushed = nearFirst ? next1 : next0;
            bool descend = hit0 || hit1;
            entry = (hit0 && nearFirst) ? next0 : next1;
            // Push: shift the registers down; the bottom one leaves for the array when all are held.
            spilling = push && held == REG_STACK;
            spillEntry = r3;
            if (push) shiftIn(r0, r1, r2, r3, pushed);
            if (push && !spilling) ++held;
            if (!descend) popEntry(entry, held, r0, r1, r2, r3);
        }
        finished = entry == ENTRY_REFILL && sp == 0u;  // popEntry: nothing held, nothing stored
        if (finished || (!spilling && isNodeEntry(entry))) break;  // done, or cut off (checked below)
        // 2. Enter an instance (its root is walked next) or intersect a leaf. Instance steps are
        // here rather than in the walk so that the walk's passes do not pay for them. Nothing marks
        // the way back: the walk tests each node against the ray of its level (topLevelNode), and
        // every entry pushed inside an instance is popped before the top-level entries beneath
        // them, so the leaves it meets belong to the instance entered last. Against a marker
        // pushed on entry and a round to leave (restoring the world ray), renders with instances
        // are faster (docs/lab/2026-12-02-lavapipe-kernel.md, "No marker for leaving an instance").
        bool consumed = false;  // `entry` is done with: take the next one
        if (HAS_INSTANCES && isInstanceEntry(entry)) {
            instance = entry & ~ENTRY_INSTANCE_BIT;
            ray = rayIntoInstance(origin, dir, instance);
            entry = rootEntry(instanceRootNode(instanceInfo(instance)));
        } else if (isLeafEntry(entry)) {
            uint first = (entry & ~ENTRY_LEAF_BIT) >> 4u;
            uint count = entry & 15u;
            if (HAS_INSTANCES && worldHoldsPrimitive(world, first)) {
                // A world leaf: no instance's entries are on the stack (they are all popped before
                // the top-level entries beneath them, and world entries sit among those), so the
                // instance ray can be overwritten; the next instance entered sets it again.
                ray = worldRay;
                instance = 0u;
            }
            uint i = 0u;
            int base = int(first * PRIM_TEXELS);
            for (; i < count; ++i, base += int(PRIM_TEXELS)) {
                if (!chargeLoop()) break;
                float t;
                vec2 bary;
                if (intersectPrimitive(ray, base, tLimit, t, bary) &&
                    (anyHit || !found || hitWins(t, instance, first + i, hit.t, hit.instance, hit.prim))) {
                    hit.t = t;
                    hit.instance = instance;
                    hit.prim = first + i;
                    hit.bary = bary;
                    found = true;
                    if (anyHit) return true;
                    tLimit = fmin(hitBucketLimit(t), tMax);
                }
            }
            if (i < count) markLoopCutOff();
            consumed = true;
        }
        // 3. The array's only store: the register entry that the walk's push shifted out of full
        // registers.
        if (spilling) {
            if (sp >= TRAVERSAL_STACK_SIZE) {
                overflow = true;
                break;
            }
            stack[sp] = spillEntry;
            ++sp;
            spilling = false;
        }
        // A node to walk (spilled mid-walk, or an instance's root) or a refill: the next round.
        if (!consumed) continue;
        // 4. The next entry.
        popEntry(entry, held, r0, r1, r2, r3);
        finished = entry == ENTRY_REFILL && sp == 0u;
        if (finished) break;
    }
    // Reported by the kernel's entry point, once per invocation: an atomic is a per-lane loop on
    // lavapipe that runs wherever it is inlined, taken or not (host/gpu/README.md, fact 3).
    if (overflow) g_rayStackOverflow = true;
    else if (!finished) markLoopCutOff();
    return found;
}

#endif
