/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "scalarExpression.H"
#include "fpTrapsHeld.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <type_traits>
#include <sstream>

// * * * * * * * * * * * * * * * * Parser  * * * * * * * * * * * * * * * * //

// Recursive descent for the ternary, unary operators, ^ and values;
// precedence climbing for the binary operators. It writes postfix code as
// it goes, folding operations on constants at once.
class Foam::scalarExpression::parser
{
public:

    using size_type = std::string::size_type;

    //- A parse error: the column (from 0) and what is wrong
    struct failure
    {
        size_type pos;
        std::string what;
    };

    //- A function or binary operator: name, arguments or precedence (higher
    //  binds tighter), instruction
    struct symbol
    {
        const char* name;
        label n;
        opCode op;
    };

    static constexpr symbol functions[] =
    {
        {"sqrt", 1, opSqrt}, {"exp", 1, opExp}, {"log", 1, opLog},
        {"log10", 1, opLog10}, {"sin", 1, opSin}, {"cos", 1, opCos},
        {"tan", 1, opTan}, {"asin", 1, opAsin}, {"acos", 1, opAcos},
        {"atan", 1, opAtan}, {"sinh", 1, opSinh}, {"cosh", 1, opCosh},
        {"tanh", 1, opTanh}, {"abs", 1, opAbs}, {"floor", 1, opFloor},
        {"ceil", 1, opCeil}, {"deg2rad", 1, opDeg2rad},
        {"rad2deg", 1, opRad2deg}, {"sign", 1, opSign},
        {"atan2", 2, opAtan2}, {"min", 2, opMin}, {"max", 2, opMax},
        {"pow", 2, opPow}, {"hypot", 2, opHypot}
    };

    // "<=" before "<", so that the longest operator matches
    static constexpr symbol binaryOperators[] =
    {
        {"||", 1, opOr}, {"&&", 2, opAnd}, {"==", 3, opEq}, {"!=", 3, opNe},
        {"<=", 4, opLe}, {">=", 4, opGe}, {"<", 4, opLt}, {">", 4, opGt},
        {"+", 5, opAdd}, {"-", 5, opSub}, {"*", 6, opMul}, {"/", 6, opDiv}
    };

    //- Deepest nesting of ternaries and unary operators (2 per parenthesis)
    static constexpr label maxNesting = 200;


private:

    const std::string& s_;
    const wordList& variables_;
    std::vector<instruction>& code_;

    //- Position in s_
    size_type pos_ = 0;

    //- Stack size after the code so far, nesting
    label depth_ = 0, nesting_ = 0;

    //- Code before this index is not folded: a jump lands here
    label fence_ = 0;


    static bool isNameChar(const char c)
    {
        return std::isalnum(c & 0xff) || c == '_';
    }

    [[noreturn]] static void fail(const size_type pos, const std::string& what)
    {
        throw failure{pos, what};
    }

    //- Skip white space; true at the end of the string
    bool atEnd()
    {
        while (pos_ < s_.size() && std::isspace(s_[pos_] & 0xff))
        {
            ++pos_;
        }
        return pos_ == s_.size();
    }

    //- Skip white space; true if the text t comes next
    bool lookingAt(const char* t)
    {
        return !atEnd() && s_.compare(pos_, std::strlen(t), t) == 0;
    }

    //- Consume the text t if it comes next
    bool accept(const char* t)
    {
        const bool found = lookingAt(t);
        pos_ += found ? std::strlen(t) : 0;
        return found;
    }

    void expect(const char* t, const std::string& what)
    {
        if (!accept(t))
        {
            fail
            (
                pos_,
                "expected " + what + ", found "
              + (atEnd() ? "the end" : "'" + s_.substr(pos_, 1) + "'")
            );
        }
    }

    void enter()
    {
        if (++nesting_ > maxNesting)
        {
            fail(pos_, "nested too deeply");
        }
    }

    //- Append a push or operation. Fold it if all its operands are
    //  constants, write x^2 as x*x, and take a right operand that is a
    //  constant or variable into the operation (one dispatch less).
    //  A pushed operand is its own code unless a jump lands on it.
    void emit(const opCode op, const int32_t arg = 0, const scalar value = 0)
    {
        const label nIn = (op < opNeg) ? 0 : (op < opAdd) ? 1 : 2;
        const label end = label(code_.size());
        bool folds = nIn > 0 && end - nIn >= fence_;
        for (label i = end - nIn; folds && i < end; ++i)
        {
            folds = (code_[i].op == opConst);
        }
        const bool pushed = end > fence_ && code_.back().op <= opVar;
        if
        (
            op == opPow && !folds && pushed
         && code_.back().op == opConst && code_.back().value == 2
        )
        {
            code_.back() = {opSqr, onStack, 0, 0};
            --depth_;
            return;
        }

        code_.push_back({op, onStack, arg, value});
        depth_ += 1 - nIn;
        if (depth_ > maxStack)
        {
            fail(pos_, "too long: needs a stack deeper than maxStack = "
                + std::to_string(maxStack));
        }
        if (folds)
        {
            const scalar result =
                run<scalar>(code_.data(), end - nIn, end + 1, nullptr);
            code_.resize(end - nIn);
            code_.push_back({opConst, onStack, 0, result});
        }
        else if (nIn == 2 && pushed)
        {
            const instruction a = code_[end - 1];
            code_.erase(code_.end() - 2);
            code_.back().right = (a.op == opConst) ? inValue : inVariable;
            code_.back().arg = a.arg;
            code_.back().value = a.value;
        }
    }

    //- Append a jump; its target is set by land
    label emitJump(const opCode op)
    {
        code_.push_back({op, onStack, 0, 0});
        depth_ -= (op == opJumpIfZero);
        return label(code_.size()) - 1;
    }

    //- Jump i lands at the end of the code so far
    void land(const label i)
    {
        fence_ = code_[i].arg = int32_t(code_.size());
    }

    // c ? a : b, right-associative: b is a ternary too
    void ternary()
    {
        enter();
        binary(1);
        if (accept("?"))
        {
            const label toElse = emitJump(opJumpIfZero);
            ternary();
            expect(":", "':' of the '?'");
            const label toEnd = emitJump(opJump);
            land(toElse);
            --depth_;
            ternary();
            land(toEnd);
        }
        --nesting_;
    }

    // Left-associative binary operators of precedence minPrec or higher
    void binary(const label minPrec)
    {
        unary();
        for (;;)
        {
            const symbol* op = binaryOperators;
            const symbol* const last = op + std::size(binaryOperators);
            while (op != last && !lookingAt(op->name))
            {
                ++op;
            }
            if (op == last || op->n < minPrec)
            {
                return;
            }
            accept(op->name);
            binary(op->n + 1);
            emit(op->op);
        }
    }

    // Unary operators bind looser than ^ (-2^2 = -4); the exponent is a
    // unary expression, which makes ^ right-associative (2^3^2 = 2^9)
    void unary()
    {
        enter();
        if (accept("-") || accept("!") || accept("+"))
        {
            const char op = s_[pos_ - 1];
            unary();
            if (op != '+')
            {
                emit(op == '-' ? opNeg : opNot);
            }
        }
        else
        {
            primary();
            if (accept("^"))
            {
                unary();
                emit(opPow);
            }
        }
        --nesting_;
    }

    // A number, (...), function call, variable or constant
    void primary()
    {
        const size_type start = pos_;
        const char c = atEnd() ? ' ' : s_[pos_];
        const char next = (pos_ + 1 < s_.size()) ? s_[pos_ + 1] : ' ';
        const bool digit = std::isdigit(c & 0xff);
        if (accept("("))
        {
            ternary();
            expect(")", "')' (unbalanced parentheses)");
        }
        else if (digit || (c == '.' && std::isdigit(next & 0xff)))
        {
            // The longest number at pos_, as C (strtod) reads it
            scalar x = 0;
            const char* first = s_.data() + pos_;
            const auto r = std::from_chars(first, s_.data() + s_.size(), x);
            if (r.ec != std::errc())
            {
                fail(pos_, "number out of range");
            }
            pos_ += r.ptr - first;
            emit(opConst, 0, x);
        }
        else if (isNameChar(c) && !digit)
        {
            while (++pos_ < s_.size() && isNameChar(s_[pos_]))
            {}
            name(s_.substr(start, pos_ - start), start);
        }
        else
        {
            fail
            (
                pos_,
                atEnd() ? "expected a value, found the end"
              : "unexpected '" + s_.substr(pos_, 1) + "'"
            );
        }
    }

    // The function call, variable or constant id at start
    void name(const std::string& id, const size_type start)
    {
        for (const symbol& f : functions)
        {
            if (id == f.name)
            {
                expect("(", "'(' after the function " + id);
                label nArgs = 0;
                if (!accept(")"))
                {
                    do
                    {
                        ternary();
                        ++nArgs;
                    } while (accept(","));
                    expect(")", "')' or ',' (unbalanced parentheses)");
                }
                if (nArgs != f.n)
                {
                    fail
                    (
                        start,
                        "function " + id + " takes " + std::to_string(f.n)
                      + " argument(s), found " + std::to_string(nArgs)
                    );
                }
                emit(f.op);
                return;
            }
        }

        const label vari = variables_.find(id);
        if (lookingAt("("))
        {
            fail(start, "unknown function " + id);
        }
        else if (vari >= 0)
        {
            emit(opVar, vari);
        }
        else if (id == "pi" || id == "e")
        {
            using namespace constant::mathematical;
            emit(opConst, 0, id == "pi" ? pi : e);
        }
        else
        {
            fail(start, "unknown variable " + id);
        }
    }


public:

    parser
    (
        const std::string& s,
        const wordList& variables,
        std::vector<instruction>& code
    )
    :
        s_(s),
        variables_(variables),
        code_(code)
    {}

    //- Parse the whole string into the code
    void parse()
    {
        if (atEnd())
        {
            fail(0, "empty expression");
        }
        ternary();
        if (!atEnd())
        {
            fail
            (
                pos_,
                s_[pos_] == ')' ? "unbalanced ')'"
              : "unexpected '" + s_.substr(pos_, 1) + "'"
            );
        }
    }
};


// * * * * * * * * * * * * * * * Dual numbers  * * * * * * * * * * * * * * //

// v + d eps with eps^2 = 0: run on these carries the derivative along
// with the value, by the chain rule of each operation. The comparisons
// compare values. Where the derivative is infinite or undefined (a zero
// denominator) it is 0, and no value that may overflow is squared, so that
// no trap fires where the value and its derivative are finite.
struct Foam::scalarExpression::dual
{
    scalar v, d;

    //- Uninitialised, as a scalar (run's stack is not zero-filled)
    dual() = default;

    dual(const scalar value, const scalar derivative = 0)
    :
        v(value),
        d(derivative)
    {}

    static scalar ratio(const scalar num, const scalar den)
    {
        return den != 0 ? num/den : 0;
    }

    // Arithmetic
    friend dual operator-(const dual& a) { return {-a.v, -a.d}; }
    friend dual operator+(const dual& b, const dual& a)
    {
        return {b.v + a.v, b.d + a.d};
    }
    friend dual operator-(const dual& b, const dual& a)
    {
        return {b.v - a.v, b.d - a.d};
    }
    friend dual operator*(const dual& b, const dual& a)
    {
        return {b.v*a.v, b.d*a.v + b.v*a.d};
    }
    friend dual operator/(const dual& b, const dual& a)
    {
        const scalar q = b.v/a.v;
        return {q, ratio(b.d - q*a.d, a.v)};
    }

    // Comparisons of the values
    friend bool operator<(const dual& b, const dual& a) { return b.v < a.v; }
    friend bool operator<=(const dual& b, const dual& a) { return b.v <= a.v; }
    friend bool operator>(const dual& b, const dual& a) { return b.v > a.v; }
    friend bool operator>=(const dual& b, const dual& a) { return b.v >= a.v; }
    friend bool operator==(const dual& b, const dual& a) { return b.v == a.v; }
    friend bool operator!=(const dual& b, const dual& a) { return b.v != a.v; }

    // Functions of one argument: f(a) and f'(a) a'
    friend dual sqrt(const dual& a)
    {
        const scalar s = std::sqrt(a.v);
        return {s, ratio(a.d, 2*s)};
    }
    friend dual exp(const dual& a)
    {
        const scalar e = std::exp(a.v);
        return {e, e*a.d};
    }
    friend dual log(const dual& a) { return {std::log(a.v), ratio(a.d, a.v)}; }
    friend dual log10(const dual& a)
    {
        return {std::log10(a.v), ratio(a.d, a.v*std::log(10.0))};
    }
    friend dual sin(const dual& a)
    {
        return {std::sin(a.v), std::cos(a.v)*a.d};
    }
    friend dual cos(const dual& a)
    {
        return {std::cos(a.v), -std::sin(a.v)*a.d};
    }
    friend dual tan(const dual& a)
    {
        const scalar c = std::cos(a.v);
        return {std::tan(a.v), ratio(a.d, c*c)};
    }
    friend dual asin(const dual& a)
    {
        return {std::asin(a.v), ratio(a.d, std::sqrt(1 - a.v*a.v))};
    }
    friend dual acos(const dual& a)
    {
        return {std::acos(a.v), -ratio(a.d, std::sqrt(1 - a.v*a.v))};
    }
    friend dual atan(const dual& a)
    {
        // 1/(1 + a^2), without squaring a large a
        const scalar d = std::abs(a.v) <= 1
          ? a.d/(1 + a.v*a.v) : (a.d/a.v)/(a.v + 1/a.v);
        return {std::atan(a.v), d};
    }
    friend dual sinh(const dual& a)
    {
        return {std::sinh(a.v), std::cosh(a.v)*a.d};
    }
    friend dual cosh(const dual& a)
    {
        return {std::cosh(a.v), std::sinh(a.v)*a.d};
    }
    friend dual tanh(const dual& a)
    {
        const scalar t = std::tanh(a.v);
        return {t, (1 - t*t)*a.d};
    }
    friend dual sqr(const dual& a) { return a*a; }
    friend dual sign(const dual& a) { return (a.v >= 0) ? 1 : -1; }
    friend dual abs(const dual& a)
    {
        return {std::abs(a.v), a.v > 0 ? a.d : a.v < 0 ? -a.d : 0};
    }
    friend dual floor(const dual& a) { return std::floor(a.v); }
    friend dual ceil(const dual& a) { return std::ceil(a.v); }
    friend dual degToRad(const dual& a)
    {
        return {degToRad(a.v), degToRad(a.d)};
    }
    friend dual radToDeg(const dual& a)
    {
        return {radToDeg(a.v), radToDeg(a.d)};
    }

    // Functions of two arguments (b, a)
    friend dual pow(const dual& b, const dual& a)
    {
        // d/db b^a = a b^(a-1): at b = 0 it is 1 for a = 1, else 0 or
        // infinite (taken as 0); d/da b^a = b^a ln b, for b > 0 only
        const scalar p = std::pow(b.v, a.v);
        const scalar dB =
            b.d == 0 ? 0
          : b.v != 0 ? a.v*std::pow(b.v, a.v - 1)*b.d
          : a.v == 1 ? b.d : 0;
        const scalar dA = (a.d != 0 && b.v > 0) ? p*std::log(b.v)*a.d : 0;
        return {p, dB + dA};
    }
    friend dual atan2(const dual& b, const dual& a)
    {
        // (a b' - b a')/(a^2 + b^2), without squaring
        const scalar h = std::hypot(b.v, a.v);
        return
        {
            std::atan2(b.v, a.v),
            ratio(ratio(a.v, h)*b.d - ratio(b.v, h)*a.d, h)
        };
    }
    friend dual hypot(const dual& b, const dual& a)
    {
        const scalar h = std::hypot(b.v, a.v);
        return {h, ratio(b.v*b.d + a.v*a.d, h)};
    }
};


// * * * * * * * * * * * * * * * * Intervals * * * * * * * * * * * * * * * //

// [lo, hi], holding every value an operation gives, as run<scalar> rounds
// it, for operands anywhere in the operands' intervals. Addition,
// multiplication, division and sqrt round correctly and rounding to
// nearest is monotone, so their results at the ends bound those between,
// with no allowance; libm's functions are widened by 8 ulps (glibc's
// are within 2 of the exact value, so the values between the ends within
// 4 of the ends' results). Where no bound is found (a pole, a domain left, a
// NaN, a NaN constant, an infinite argument of sin or cos) the interval is
// whole, [-inf, inf], and may hold NaN: every operation on it gives whole
// (a NaN need not reach the result: std::max(NaN, 0) is NaN,
// std::max(0, NaN) is 0, and a comparison with NaN is a number) but the
// comparisons, which give 0 or 1 whatever their operands. Every rule
// relies on this: an interval that is not whole holds no NaN.
struct Foam::scalarExpression::interval
{
    scalar lo, hi;

    //- Uninitialised, as a scalar
    interval() = default;

    //- The value v (whole for a NaN: a folded 0/0 or sqrt(-1))
    interval(const scalar v)
    :
        lo(v == v ? v : -inf),
        hi(v == v ? v : inf)
    {}

    interval(const scalar l, const scalar h)
    :
        lo(l),
        hi(h)
    {}

    static constexpr scalar inf = std::numeric_limits<scalar>::infinity();

    static interval whole() { return {-inf, inf}; }

    bool isWhole() const
    {
        return (lo == -inf && hi == inf) || lo != lo || hi != hi;
    }

    //- [l, h] from operands a (and b), whole if one is or l, h are NaN
    static interval of(const interval& a, const scalar l, const scalar h)
    {
        return (a.isWhole() || l != l || h != h) ? whole() : interval(l, h);
    }

    static interval of
    (
        const interval& b,
        const interval& a,
        const scalar l,
        const scalar h
    )
    {
        return b.isWhole() ? whole() : of(a, l, h);
    }

    //- [l, h] of a libm function, widened
    static interval libm(const interval& a, scalar l, scalar h)
    {
        for (int k = 0; k < 8; ++k)
        {
            l = std::nextafter(l, -inf);
            h = std::nextafter(h, inf);
        }
        return of(a, l, h);
    }

    //- Smallest and largest of four values, NaN if one is
    static interval hull4(const scalar p[4])
    {
        scalar l = p[0], h = p[0];
        bool nan = (p[0] != p[0]);
        for (int k = 1; k < 4; ++k)
        {
            l = std::min(l, p[k]);
            h = std::max(h, p[k]);
            nan = nan || (p[k] != p[k]);
        }
        return nan ? interval(NAN, NAN) : interval(l, h);
    }

    bool holdsZero() const { return lo <= 0 && 0 <= hi; }

    //- The ternary's condition: may be zero, may be nonzero (a NaN
    //  is not zero)
    bool mayBeZero() const { return holdsZero(); }
    bool mayBeNonzero() const { return !(lo == 0 && hi == 0); }

    //- Both operands' values
    friend interval hull(const interval& b, const interval& a)
    {
        return of(b, a, std::min(b.lo, a.lo), std::max(b.hi, a.hi));
    }

    //- A truth value: 1, 0 or either
    static interval truth(const bool isTrue, const bool isFalse)
    {
        return isTrue ? interval(1) : isFalse ? interval(0) : interval(0, 1);
    }

    //- Does a reach x0 + k period for some whole k (within 1e-6: a spare
    //  point only loosens a bound)? a finite, |ends| < 1e6
    static bool reaches
    (
        const interval& a,
        const scalar x0,
        const scalar period
    )
    {
        const scalar k = std::floor((a.lo - x0)/period);
        for (int dk = 0; dk <= 2; ++dk)
        {
            const scalar x = x0 + period*(k + dk);
            if (x >= a.lo - 1e-6 && x <= a.hi + 1e-6)
            {
                return true;
            }
        }
        return a.hi - a.lo >= period;
    }

    //- The extremes of sin (phase 0) or cos (phase pi/2) over a: at the
    //  ends, or 1 at pi/2 - phase + 2 k pi, -1 at -pi/2 - phase + 2 k pi
    //  inside it (found with a margin: a spare extreme only loosens)
    static interval periodic
    (
        const interval& a,
        const scalar phase,
        scalar (*f)(scalar)
    )
    {
        // (sin and cos of an infinity are NaN: whole)
        constexpr scalar pi = constant::mathematical::pi;
        if (a.isWhole() || !(std::isfinite(a.lo) && std::isfinite(a.hi)))
        {
            return whole();
        }
        if (!(std::abs(a.lo) < 1e6 && std::abs(a.hi) < 1e6))
        {
            return interval(-1, 1);
        }
        const scalar fLo = f(a.lo), fHi = f(a.hi);
        const interval ends(libm(a, std::min(fLo, fHi), std::max(fLo, fHi)));
        return
        {
            reaches(a, -pi/2 - phase, 2*pi) ? -1 : std::max(ends.lo, -1.0),
            reaches(a, pi/2 - phase, 2*pi) ? 1 : std::min(ends.hi, 1.0)
        };
    }

    //- Range of |a|
    static interval magnitude(const interval& a)
    {
        const scalar l = std::abs(a.lo), h = std::abs(a.hi);
        return {a.holdsZero() ? 0 : std::min(l, h), std::max(l, h)};
    }

    // Arithmetic
    friend interval operator-(const interval& a) { return of(a, -a.hi, -a.lo); }
    friend interval operator+(const interval& b, const interval& a)
    {
        return of(b, a, b.lo + a.lo, b.hi + a.hi);
    }
    friend interval operator-(const interval& b, const interval& a)
    {
        return of(b, a, b.lo - a.hi, b.hi - a.lo);
    }
    friend interval operator*(const interval& b, const interval& a)
    {
        const scalar p[4] = {b.lo*a.lo, b.lo*a.hi, b.hi*a.lo, b.hi*a.hi};
        const interval r(hull4(p));
        return of(b, a, r.lo, r.hi);
    }
    friend interval operator/(const interval& b, const interval& a)
    {
        if (a.holdsZero())
        {
            return whole();
        }
        const scalar q[4] = {b.lo/a.lo, b.lo/a.hi, b.hi/a.lo, b.hi/a.hi};
        const interval r(hull4(q));
        return of(b, a, r.lo, r.hi);
    }
    friend interval sqr(const interval& a)
    {
        const interval m(magnitude(a));
        return of(a, m.lo*m.lo, m.hi*m.hi);
    }

    // Comparisons: 1, 0 or either
    friend interval operator<(const interval& b, const interval& a)
    {
        const bool known = !b.isWhole() && !a.isWhole();
        return truth(known && b.hi < a.lo, known && b.lo >= a.hi);
    }
    friend interval operator<=(const interval& b, const interval& a)
    {
        const bool known = !b.isWhole() && !a.isWhole();
        return truth(known && b.hi <= a.lo, known && b.lo > a.hi);
    }
    friend interval operator>(const interval& b, const interval& a)
    {
        return a < b;
    }
    friend interval operator>=(const interval& b, const interval& a)
    {
        return a <= b;
    }
    friend interval operator==(const interval& b, const interval& a)
    {
        const bool known = !b.isWhole() && !a.isWhole();
        return truth
        (
            known && b.lo == b.hi && a.lo == a.hi && b.lo == a.lo,
            known && (b.hi < a.lo || a.hi < b.lo)
        );
    }
    friend interval operator!=(const interval& b, const interval& a)
    {
        const interval eq(b == a);
        return {1 - eq.hi, 1 - eq.lo};
    }
    friend interval operator&&(const interval& b, const interval& a)
    {
        return {std::min(b.lo, a.lo), std::min(b.hi, a.hi)};
    }
    friend interval operator||(const interval& b, const interval& a)
    {
        return {std::max(b.lo, a.lo), std::max(b.hi, a.hi)};
    }

    // Functions of one argument
    friend interval sqrt(const interval& a)
    {
        return a.lo < 0 ? whole() : of(a, std::sqrt(a.lo), std::sqrt(a.hi));
    }
    friend interval exp(const interval& a)
    {
        const interval r(libm(a, std::exp(a.lo), std::exp(a.hi)));
        return of(a, std::max(r.lo, 0.0), r.hi);
    }
    friend interval log(const interval& a)
    {
        return a.lo > 0 ? libm(a, std::log(a.lo), std::log(a.hi)) : whole();
    }
    friend interval log10(const interval& a)
    {
        return
            a.lo > 0 ? libm(a, std::log10(a.lo), std::log10(a.hi)) : whole();
    }
    friend interval sin(const interval& a)
    {
        return periodic(a, 0, [](const scalar x) { return std::sin(x); });
    }
    friend interval cos(const interval& a)
    {
        return periodic
        (
            a, constant::mathematical::pi/2,
            [](const scalar x) { return std::cos(x); }
        );
    }
    friend interval tan(const interval& a)
    {
        // Increasing between its poles, pi/2 + k pi
        constexpr scalar pi = constant::mathematical::pi;
        if
        (
            !(std::abs(a.lo) < 1e6 && std::abs(a.hi) < 1e6)
         || reaches(a, pi/2, pi)
        )
        {
            return whole();
        }
        return libm(a, std::tan(a.lo), std::tan(a.hi));
    }
    friend interval asin(const interval& a)
    {
        return (a.lo >= -1 && a.hi <= 1)
            ? libm(a, std::asin(a.lo), std::asin(a.hi)) : whole();
    }
    friend interval acos(const interval& a)
    {
        return (a.lo >= -1 && a.hi <= 1)
            ? libm(a, std::acos(a.hi), std::acos(a.lo)) : whole();
    }
    friend interval atan(const interval& a)
    {
        return libm(a, std::atan(a.lo), std::atan(a.hi));
    }
    friend interval sinh(const interval& a)
    {
        return libm(a, std::sinh(a.lo), std::sinh(a.hi));
    }
    friend interval cosh(const interval& a)
    {
        const interval m(magnitude(a));
        const interval r(libm(a, std::cosh(m.lo), std::cosh(m.hi)));
        return of(a, std::max(r.lo, std::nextafter(1.0, 0.0)), r.hi);
    }
    friend interval tanh(const interval& a)
    {
        const interval r(libm(a, std::tanh(a.lo), std::tanh(a.hi)));
        return of(a, std::max(r.lo, -1.0), std::min(r.hi, 1.0));
    }
    friend interval abs(const interval& a)
    {
        const interval m(magnitude(a));
        return of(a, m.lo, m.hi);
    }
    friend interval floor(const interval& a)
    {
        return of(a, std::floor(a.lo), std::floor(a.hi));
    }
    friend interval ceil(const interval& a)
    {
        return of(a, std::ceil(a.lo), std::ceil(a.hi));
    }
    friend interval degToRad(const interval& a)
    {
        return of(a, degToRad(a.lo), degToRad(a.hi));
    }
    friend interval radToDeg(const interval& a)
    {
        return of(a, radToDeg(a.lo), radToDeg(a.hi));
    }
    friend interval sign(const interval& a)
    {
        return of(a, Foam::sign(a.lo), Foam::sign(a.hi));
    }

    // Functions of two arguments (b, a)
    friend interval pow(const interval& b, const interval& a)
    {
        if (b.isWhole() || a.isWhole())
        {
            return whole();
        }
        if (b.lo > 0 || (b.lo >= 0 && a.lo > 0))
        {
            // Monotone in b and in a: extremes at the corners
            const scalar p[4] =
            {
                std::pow(b.lo, a.lo), std::pow(b.lo, a.hi),
                std::pow(b.hi, a.lo), std::pow(b.hi, a.hi)
            };
            const interval r(hull4(p));
            return libm(a, r.lo, r.hi);
        }
        // A negative base: a whole power n only, monotone in b on either
        // side of 0, through 0 for n > 0
        const scalar n = a.lo;
        if (a.hi != n || std::floor(n) != n || std::abs(n) > 1e15)
        {
            return whole();
        }
        if (n == 0)
        {
            return interval(1);
        }
        if (n < 0 && b.holdsZero())
        {
            return whole();
        }
        const scalar ends[2] = {std::pow(b.lo, n), std::pow(b.hi, n)};
        const bool even = (std::fmod(n, 2) == 0);
        if (even && n > 0 && b.holdsZero())
        {
            return libm(a, 0, std::max(ends[0], ends[1]));
        }
        return
            libm(a, std::min(ends[0], ends[1]), std::max(ends[0], ends[1]));
    }
    friend interval atan2(const interval& b, const interval& a)
    {
        constexpr scalar pi = constant::mathematical::pi;
        return libm(hull(b, a), -pi, pi);
    }
    friend interval hypot(const interval& b, const interval& a)
    {
        const interval mb(magnitude(b)), ma(magnitude(a));
        const interval r
        (
            libm(hull(b, a), std::hypot(mb.lo, ma.lo), std::hypot(mb.hi, ma.hi))
        );
        return of(r, std::max(r.lo, 0.0), r.hi);
    }
    friend interval min(const interval& b, const interval& a)
    {
        return of(b, a, std::min(b.lo, a.lo), std::min(b.hi, a.hi));
    }
    friend interval max(const interval& b, const interval& a)
    {
        return of(b, a, std::max(b.lo, a.lo), std::max(b.hi, a.hi));
    }
};


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class Type>
Type Foam::scalarExpression::run
(
    const instruction* code,
    const label first,
    const label last,
    const Type* vars
)
{
    // The scalar functions by name; a dual's are found by argument lookup
    using std::sqrt; using std::exp; using std::log; using std::log10;
    using std::sin; using std::cos; using std::tan; using std::asin;
    using std::acos; using std::atan; using std::sinh; using std::cosh;
    using std::tanh; using std::abs; using std::floor; using std::ceil;
    using std::pow; using std::atan2; using std::hypot; using std::min;
    using std::max;

    Type s[maxStack];
    label top = -1;

    for (label pc = first; pc < last; ++pc)
    {
        const instruction& c = code[pc];

        // The operand of a unary operation, the right one of a binary
        Type a = 0;
        if (c.op >= opNeg)
        {
            a = (c.right == inValue) ? Type(c.value)
              : (c.right == inVariable) ? vars[c.arg] : s[top];
            top -= (c.op >= opAdd && c.right == onStack);
        }
        const Type b = (c.op >= opAdd) ? s[top] : Type(0);

        switch (c.op)
        {
            case opConst: s[++top] = c.value; break;
            case opVar: s[++top] = vars[c.arg]; break;
            case opJumpIfZero:
            {
                const Type cond = s[top--];
                if constexpr (std::is_same<Type, interval>::value)
                {
                    if (cond.mayBeZero() && cond.mayBeNonzero())
                    {
                        // Either branch: both, from empty stacks (the
                        // 'then' code ends in the jump over the 'else')
                        const label end = code[c.arg - 1].arg;
                        s[++top] = hull
                        (
                            run(code, pc + 1, c.arg - 1, vars),
                            run(code, c.arg, end, vars)
                        );
                        pc = end - 1;
                    }
                    else
                    {
                        pc = cond.mayBeZero() ? c.arg - 1 : pc;
                    }
                }
                else
                {
                    pc = (cond == 0) ? c.arg - 1 : pc;
                }
                break;
            }
            case opJump: pc = c.arg - 1; break;
            case opNeg: s[top] = -a; break;
            case opNot: s[top] = Type(a == 0); break;
            case opSqr: s[top] = sqr(a); break;
            case opSqrt: s[top] = sqrt(a); break;
            case opExp: s[top] = exp(a); break;
            case opLog: s[top] = log(a); break;
            case opLog10: s[top] = log10(a); break;
            case opSin: s[top] = sin(a); break;
            case opCos: s[top] = cos(a); break;
            case opTan: s[top] = tan(a); break;
            case opAsin: s[top] = asin(a); break;
            case opAcos: s[top] = acos(a); break;
            case opAtan: s[top] = atan(a); break;
            case opSinh: s[top] = sinh(a); break;
            case opCosh: s[top] = cosh(a); break;
            case opTanh: s[top] = tanh(a); break;
            case opAbs: s[top] = abs(a); break;
            case opFloor: s[top] = floor(a); break;
            case opCeil: s[top] = ceil(a); break;
            case opDeg2rad: s[top] = degToRad(a); break;
            case opRad2deg: s[top] = radToDeg(a); break;
            case opSign: s[top] = sign(a); break;
            case opAdd: s[top] = b + a; break;
            case opSub: s[top] = b - a; break;
            case opMul: s[top] = b*a; break;
            case opDiv: s[top] = b/a; break;
            case opPow: s[top] = pow(b, a); break;
            case opLt: s[top] = Type(b < a); break;
            case opLe: s[top] = Type(b <= a); break;
            case opGt: s[top] = Type(b > a); break;
            case opGe: s[top] = Type(b >= a); break;
            case opEq: s[top] = Type(b == a); break;
            case opNe: s[top] = Type(b != a); break;
            case opAnd: s[top] = Type(b != 0 && a != 0); break;
            case opOr: s[top] = Type(b != 0 || a != 0); break;
            case opAtan2: s[top] = atan2(b, a); break;
            case opMin: s[top] = min(b, a); break;
            case opMax: s[top] = max(b, a); break;
            case opHypot: s[top] = hypot(b, a); break;
        }
    }

    return s[0];
}


// The scalar code is what value() runs
template Foam::scalar Foam::scalarExpression::run<Foam::scalar>
(
    const instruction*,
    label,
    label,
    const scalar*
);


std::string Foam::scalarExpression::compile()
{
    code_.clear();
    if (variables_.size() > maxVariables)
    {
        return "more variables than maxVariables = "
            + std::to_string(maxVariables);
    }
    try
    {
        // Folding constants may give NaN or inf (1/0, 1e300*1e300): a value
        // like any other, refused by the caller where it is evaluated
        fpTrapsHeld masked;
        parser(expr_, variables_, code_).parse();
        return "";
    }
    catch (const parser::failure& err)
    {
        // Show the expression on one line, so that the caret lines up
        std::string shown(expr_);
        for (char& c : shown)
        {
            c = std::isspace(c & 0xff) ? ' ' : c;
        }

        std::ostringstream os;
        os  << err.what << " at column " << err.pos + 1 << "\n\n"
            << "    " << shown << '\n'
            << "    " << std::string(err.pos, ' ') << "^\n\n"
            << "Variables:";
        for (const word& var : variables_)
        {
            os  << ' ' << var;
        }
        os  << (variables_.empty() ? " none" : "") << '\n'
            << "Constants: pi e\n"
            << "Operators: + - * / ^ < <= > >= == != && || ! c ? a : b\n"
            << "Functions of a:";
        for (const label nArgs : {1, 2})
        {
            for (const parser::symbol& f : parser::functions)
            {
                os  << (f.n == nArgs ? " " + std::string(f.name) : "");
            }
            os  << (nArgs == 1 ? "\nFunctions of (a, b):" : "\n");
        }
        code_.clear();
        return os.str();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scalarExpression::scalarExpression
(
    const dictionary& dict,
    const word& keyword,
    const wordList& variables
)
:
    expr_(dict.get<string>(keyword)),
    variables_(variables)
{
    const std::string err(compile());
    if (!err.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Invalid expression for keyword " << keyword << ": "
            << err.c_str() << exit(FatalIOError);
    }
}


Foam::scalarExpression::scalarExpression
(
    const std::string& expr,
    const wordList& variables,
    const std::string& description
)
:
    expr_(expr),
    variables_(variables)
{
    const std::string err(compile());
    if (!err.empty())
    {
        FatalErrorInFunction
            << "Invalid expression for " << description.c_str() << ": "
            << err.c_str() << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::scalarExpression::value
(
    const scalar* vars,
    const label var,
    scalar& derivative
) const
{
    dual x[maxVariables];
    for (label i = 0; i < variables_.size(); ++i)
    {
        x[i] = dual(vars[i], i == var);
    }
    const dual result = run(code_.data(), 0, code_.size(), x);
    derivative = result.d;
    return result.v;
}


Foam::scalarMinMax Foam::scalarExpression::bounds
(
    const scalarMinMax* ranges
) const
{
    // (Ends at an infinity or a pole: no trap)
    fpTrapsHeld masked;
    interval x[maxVariables];
    for (label i = 0; i < variables_.size(); ++i)
    {
        x[i] = interval::of(0, ranges[i].min(), ranges[i].max());
    }
    const interval result = run(code_.data(), 0, code_.size(), x);
    return scalarMinMax(result.lo, result.hi);
}


bool Foam::scalarExpression::dependsOn(const word& var) const
{
    const label vari = variables_.find(var);
    for (const instruction& c : code_)
    {
        const bool readsVar = (c.op == opVar || c.right == inVariable);
        if (readsVar && c.arg == vari)
        {
            return true;
        }
    }
    return false;
}


void Foam::scalarExpression::write(Ostream& os) const
{
    os  << expr_;
}


// ************************************************************************* //
