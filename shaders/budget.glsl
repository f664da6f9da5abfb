// Loop accounting. Mesa before 25 silently ends every loop after 65,535 back-edges per
// invocation (one counter for the whole inlined kernel), which would leave a silently wrong pixel.
// Every loop of the kernel charges this budget; when LOOP_BUDGET is spent the invocation stops and
// reports it, so the host raises an error instead of writing a wrong image.
#ifndef VKRT_BUDGET_GLSL
#define VKRT_BUDGET_GLSL

uint g_loopIterations = 0u;
bool g_budgetExceeded = false;

// Charges one loop iteration; false once the budget is spent.
bool chargeLoop() {
    g_loopIterations += 1u;
    if (g_loopIterations > LOOP_BUDGET) g_budgetExceeded = true;
    return !g_budgetExceeded;
}

#endif
