// Loop accounting. Mesa before 25 silently ends every loop after 65,535 passes per invocation
// (one counter per group of 8 lanes, shared by every loop of the inlined kernel and charged for
// the slowest lane, so a lane's own count cannot predict it: host/gpu/README.md). Two guards:
//  - every loop checks on exit that it finished its work (its own condition ended it, or a
//    deliberate break) and otherwise sets g_loopCutOff: this catches the limiter whatever the
//    divergence, because once it fires every loop still running ends early;
//  - every loop charges a per-invocation budget (LOOP_BUDGET), which bounds the work of one
//    sample on drivers without a limiter too (a runaway loop becomes an error, not a hang).
// The kernel reports either through RenderStatus, so the host raises an error instead of writing
// a wrong image.
#ifndef VKRT_BUDGET_GLSL
#define VKRT_BUDGET_GLSL

uint g_loopIterations = 0u;
bool g_budgetExceeded = false;
bool g_loopCutOff = false;

// Charges one loop iteration; false once the budget is spent.
bool chargeLoop() {
    g_loopIterations += 1u;
    if (g_loopIterations > LOOP_BUDGET) g_budgetExceeded = true;
    return !g_budgetExceeded;
}

// Records that a loop ended before finishing its work. sampling.h calls it through this macro
// (the C++ side, which has no limiter, defines it empty), so budget.glsl precedes sampling.h.
void markLoopCutOff() { g_loopCutOff = true; }
#define VKRT_LOOP_CUT_OFF() markLoopCutOff()
// A shared header's bounded loop charges its passes through this (the budget's error reports a
// sample that ran out; the loop itself still ends after its bound).
#define VKRT_LOOP_CHARGE() chargeLoop()

#endif
