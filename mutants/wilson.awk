# The 95 % Wilson score interval of c caught mutants among n viable ones, shared by run.sh (the
# score of a run) and table.sh (the table of docs/mutants.md). Sets WILSON_P, WILSON_LO and
# WILSON_HI (clamped to [0, 1]); callers handle n = 0 themselves.
function wilson_interval(c, n,    z, d, m, h) {
    WILSON_P = c / n; z = 1.96; d = 1 + z*z/n
    m = (WILSON_P + z*z/(2*n)) / d; h = z * sqrt(WILSON_P*(1-WILSON_P)/n + z*z/(4*n*n)) / d
    WILSON_LO = m - h < 0 ? 0 : m - h
    WILSON_HI = m + h > 1 ? 1 : m + h
}
