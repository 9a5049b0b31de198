// Tallies of NaN, Inf, negative and out-of-range results, so millions of evaluations come back
// as a few counters: each invocation counts locally, then adds its counts to one record per
// checked quantity. Must match CheckRecord in check_records.h.
#ifndef STABILITY_CHECKS_GLSL
#define STABILITY_CHECKS_GLSL

struct CheckRecord {
    uint evaluations;
    uint nanCount;
    uint infCount;
    uint negativeCount;
    uint outOfRangeCount;  // finite but outside [lower, upper] of the quantity
    uint firstFailure;     // smallest failing case index; 0xffffffff when none failed
    uint maxFiniteBits;    // floatBitsToUint of the largest finite |value| (orders like floats)
    uint pad;
};

layout(std430, binding = 0) buffer CheckRecords {
    CheckRecord records[];
};

// Largest finite float: as an upper bound it lets every finite value through.
const float kNoUpperBound = 3.402823466e38;

struct Tally {
    uint evaluations;
    uint nanCount;
    uint infCount;
    uint negativeCount;
    uint outOfRangeCount;
    uint firstFailure;
    float maxFinite;
};

Tally newTally() {
    return Tally(0u, 0u, 0u, 0u, 0u, 0xffffffffu, 0.0);
}

// Classified from the bit pattern, so no compiler assumption about NaN can hide one.
void tally(inout Tally t, float value, float lower, float upper, uint caseIndex) {
    uint bits = floatBitsToUint(value);
    bool nonFinite = (bits & 0x7f800000u) == 0x7f800000u;
    bool isNan = nonFinite && (bits & 0x007fffffu) != 0u;
    bool negative = !nonFinite && value < 0.0;
    bool outOfRange = !nonFinite && (value < lower || value > upper);
    t.evaluations += 1u;
    if (isNan) t.nanCount += 1u;
    if (nonFinite && !isNan) t.infCount += 1u;
    if (negative) t.negativeCount += 1u;
    if (outOfRange) t.outOfRangeCount += 1u;
    if (nonFinite || outOfRange) t.firstFailure = min(t.firstFailure, caseIndex);
    if (!nonFinite) t.maxFinite = max(t.maxFinite, abs(value));
}

void tally3(inout Tally t, vec3 value, float lower, float upper, uint caseIndex) {
    tally(t, value.x, lower, upper, caseIndex);
    tally(t, value.y, lower, upper, caseIndex);
    tally(t, value.z, lower, upper, caseIndex);
}

// A yes/no property (e.g. bit-identical reduction): a failure counts as out of range.
void tallyCondition(inout Tally t, bool holds, uint caseIndex) {
    tally(t, holds ? 0.0 : 1.0, 0.0, 0.0, caseIndex);
}

void flushTally(uint record, Tally t) {
    atomicAdd(records[record].evaluations, t.evaluations);
    if (t.nanCount > 0u) atomicAdd(records[record].nanCount, t.nanCount);
    if (t.infCount > 0u) atomicAdd(records[record].infCount, t.infCount);
    if (t.negativeCount > 0u) atomicAdd(records[record].negativeCount, t.negativeCount);
    if (t.outOfRangeCount > 0u) atomicAdd(records[record].outOfRangeCount, t.outOfRangeCount);
    if (t.firstFailure != 0xffffffffu) atomicMin(records[record].firstFailure, t.firstFailure);
    atomicMax(records[record].maxFiniteBits, floatBitsToUint(t.maxFinite));
}

#endif
