// Double-precision transcendental functions for scenes compiled with precision "double" (GLSL has
// no double overloads of sin, cos, tan, asin, acos, atan, pow, exp, log, exp2, log2). The compiler
// routes node bodies' calls here and adds the componentwise vector forms. Written in the subset
// that also compiles as C++, so a test compares every function with <cmath>; the compiler gives
// every literal the lf suffix. `precise` keeps drivers from reassociating the range reductions
// (Mesa's NIR otherwise folds (x - k c1) - k c2 into x - k (c1 + c2) and loses the split). Accuracy: a few ulp (about 1e-15 relative); sin, cos and tan reduce
// their argument exactly up to |x| ~ 1.6e6, beyond that the error grows like |x| * 1e-16.

const double FG_D_PIO2_HI = 1.5707963267948966;
const double FG_D_PIO2_LO = 6.123233995736766e-17;
const double FG_D_PI_HI = 3.141592653589793;
const double FG_D_PI_LO = 1.2246467991473532e-16;
const double FG_D_PIO6_HI = 0.5235987755982989;
const double FG_D_PIO6_LO = -5.360408832255455e-17;
const double FG_D_SQRT3 = 1.7320508075688772;
const double FG_D_TAN_PI_12 = 0.2679491924311227;
const double FG_D_LN2 = 0.6931471805599453;
const double FG_D_INV_LN2 = 1.4426950408889634;
const double FG_D_2_OVER_PI = 0.6366197723675814;
// ln 2 and pi / 2 split so that k times the first part is exact for |k| < 2^20 (fdlibm's values).
const double FG_D_LN2_HI = 6.93147180369123816490e-01;
const double FG_D_LN2_LO = 1.90821492927058770002e-10;
const double FG_D_PIO2_1 = 1.57079632673412561417e+00;
const double FG_D_PIO2_2 = 6.07710050630396597660e-11;
const double FG_D_PIO2_3 = 2.02226624871116645580e-21;

// e^r for |r| <= 0.35: Taylor series to r^14 / 14! (truncation below 5e-18), Horner form.
double fg_d_exp_kernel(double r)
{
    return 1.0 + r * (1.0 + r * (0.5 + r * (0.16666666666666666 + r * (0.041666666666666664 +
           r * (0.008333333333333333 + r * (0.001388888888888889 + r * (0.0001984126984126984 +
           r * (2.48015873015873e-05 + r * (2.7557319223985893e-06 + r * (2.755731922398589e-07 +
           r * (2.505210838544172e-08 + r * (2.08767569878681e-09 + r * (1.6059043836821613e-10 +
           r * 1.1470745597729725e-11)))))))))))));
}

// e^x = 2^k e^r with r = x - k ln 2. Clamped where double over- or underflows, so it never answers
// Inf (GLSL leaves exp's overflow to the driver).
double fg_d_exp(double x)
{
    double xc = clamp(x, -708.0, 709.0);
    double k = floor(xc * FG_D_INV_LN2 + 0.5);
    precise double r = (xc - k * FG_D_LN2_HI) - k * FG_D_LN2_LO;
    return ldexp(fg_d_exp_kernel(r), int(k));
}

// 2^x = 2^n e^(f ln 2), n the nearest integer: f is exact, so large x lose nothing.
double fg_d_exp2(double x)
{
    double xc = clamp(x, -1021.0, 1023.0);
    double n = floor(xc + 0.5);
    precise double r = (xc - n) * FG_D_LN2;
    return ldexp(fg_d_exp_kernel(r), int(n));
}

// log x = e ln 2 + log m with x = m 2^e, m in [sqrt(1/2), sqrt(2)): log m = 2 atanh(s),
// s = (m - 1) / (m + 1), |s| <= 0.172, series to s^23. x <= 0 (undefined in GLSL) answers the log of
// the smallest double instead of -Inf or NaN.
double fg_d_log(double x)
{
    if (!(x > 0.0)) return -745.1332191019412;
    int e = 0;
    double m = frexp(x, e);
    if (m < 0.7071067811865476) {
        m = m * 2.0;
        e = e - 1;
    }
    double s = (m - 1.0) / (m + 1.0);
    double s2 = s * s;
    double tail = s2 * (0.3333333333333333 + s2 * (0.2 + s2 * (0.14285714285714285 + s2 * (0.1111111111111111 +
                  s2 * (0.09090909090909091 + s2 * (0.07692307692307693 + s2 * (0.06666666666666667 +
                  s2 * (0.058823529411764705 + s2 * (0.05263157894736842 + s2 * (0.047619047619047616 +
                  s2 * 0.043478260869565216))))))))));
    double de = double(e);
    precise double result = de * FG_D_LN2_HI + (2.0 * s + (2.0 * s * tail + de * FG_D_LN2_LO));
    return result;
}

double fg_d_log2(double x)
{
    return fg_d_log(x) * FG_D_INV_LN2;
}

// x^y as e^(y log x); GLSL leaves x < 0 undefined: 0 here, as for x = 0 with y > 0.
double fg_d_pow(double x, double y)
{
    if (y == 0.0) return 1.0;
    if (!(x > 0.0)) return 0.0;
    return fg_d_exp(y * fg_d_log(x));
}

// x - k pi/2 for the nearest integer k (Cody-Waite in three parts), and k mod 4.
double fg_d_reduce(double x, OUT(int) quadrant)
{
    double k = floor(x * FG_D_2_OVER_PI + 0.5);
    quadrant = int(k - 4.0 * floor(k * 0.25));
    precise double r = ((x - k * FG_D_PIO2_1) - k * FG_D_PIO2_2) - k * FG_D_PIO2_3;
    return r;
}

// sin and cos on |r| <= pi/4: Taylor series to r^17 and r^18 (truncation below 5e-17).
double fg_d_sin_kernel(double r)
{
    double r2 = r * r;
    return r + r * r2 * (-0.16666666666666666 + r2 * (0.008333333333333333 + r2 * (-0.0001984126984126984 +
           r2 * (2.7557319223985893e-06 + r2 * (-2.505210838544172e-08 + r2 * (1.6059043836821613e-10 +
           r2 * (-7.647163731819816e-13 + r2 * 2.8114572543455206e-15)))))));
}

double fg_d_cos_kernel(double r)
{
    double r2 = r * r;
    return 1.0 - 0.5 * r2 + r2 * r2 * (0.041666666666666664 + r2 * (-0.001388888888888889 +
           r2 * (2.48015873015873e-05 + r2 * (-2.755731922398589e-07 + r2 * (2.08767569878681e-09 +
           r2 * (-1.1470745597729725e-11 + r2 * (4.779477332387385e-14 + r2 * -1.5619206968586225e-16)))))));
}

double fg_d_sin(double x)
{
    int q = 0;
    double r = fg_d_reduce(x, q);
    if (q == 0) return fg_d_sin_kernel(r);
    if (q == 1) return fg_d_cos_kernel(r);
    if (q == 2) return -fg_d_sin_kernel(r);
    return -fg_d_cos_kernel(r);
}

double fg_d_cos(double x)
{
    int q = 0;
    double r = fg_d_reduce(x, q);
    if (q == 0) return fg_d_cos_kernel(r);
    if (q == 1) return -fg_d_sin_kernel(r);
    if (q == 2) return -fg_d_cos_kernel(r);
    return fg_d_sin_kernel(r);
}

// tan at an odd multiple of pi/2 (never exact in double, but r may round to 0) answers a huge
// finite value rather than Inf.
double fg_d_tan(double x)
{
    int q = 0;
    double r = fg_d_reduce(x, q);
    double s = fg_d_sin_kernel(r);
    double c = fg_d_cos_kernel(r);
    if (q == 0 || q == 2) return s / c;
    return s == 0.0 ? -1e300 : -c / s;
}

// atan on [0, 1]: above tan(pi/12) shifted by pi/6, then the series to u^27 (|u| <= 0.268).
double fg_d_atan_unit(double t)
{
    double base = 0.0;
    double base_lo = 0.0;
    precise double u = t;
    if (t > FG_D_TAN_PI_12) {
        u = (t * FG_D_SQRT3 - 1.0) / (t + FG_D_SQRT3);
        base = FG_D_PIO6_HI;
        base_lo = FG_D_PIO6_LO;
    }
    double u2 = u * u;
    double tail = u2 * (-0.3333333333333333 + u2 * (0.2 + u2 * (-0.14285714285714285 + u2 * (0.1111111111111111 +
                  u2 * (-0.09090909090909091 + u2 * (0.07692307692307693 + u2 * (-0.06666666666666667 +
                  u2 * (0.058823529411764705 + u2 * (-0.05263157894736842 + u2 * (0.047619047619047616 +
                  u2 * (-0.043478260869565216 + u2 * (0.04 + u2 * -0.037037037037037035))))))))))));
    precise double result = base + (u + (u * tail + base_lo));
    return result;
}

// atan2; (0, 0) answers 0, as fg_safe_atan does.
double fg_d_atan2(double y, double x)
{
    double ax = abs(x);
    double ay = abs(y);
    if (ax == 0.0 && ay == 0.0) return 0.0;
    precise double a = ay <= ax ? fg_d_atan_unit(ay / ax) : (FG_D_PIO2_HI - fg_d_atan_unit(ax / ay)) + FG_D_PIO2_LO;
    if (x < 0.0) a = (FG_D_PI_HI - a) + FG_D_PI_LO;
    return y < 0.0 ? -a : a;
}

double fg_d_atan(double x)
{
    return fg_d_atan2(x, 1.0);
}

// asin and acos through atan2 of the two legs; (1 - x)(1 + x) keeps the small leg accurate near
// +-1. Arguments past +-1 (undefined in GLSL) are clamped.
double fg_d_asin(double x)
{
    double xc = clamp(x, -1.0, 1.0);
    return fg_d_atan2(xc, sqrt((1.0 - xc) * (1.0 + xc)));
}

double fg_d_acos(double x)
{
    double xc = clamp(x, -1.0, 1.0);
    return fg_d_atan2(sqrt((1.0 - xc) * (1.0 + xc)), xc);
}
