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
                run<scalar>(&code_[end - nIn], nIn + 1, nullptr);
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


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class Type>
Type Foam::scalarExpression::run
(
    const instruction* code,
    const label n,
    const Type* vars
)
{
    // The scalar functions by name; a dual's are found by argument lookup
    using std::sqrt; using std::exp; using std::log; using std::log10;
    using std::sin; using std::cos; using std::tan; using std::asin;
    using std::acos; using std::atan; using std::sinh; using std::cosh;
    using std::tanh; using std::abs; using std::floor; using std::ceil;
    using std::pow; using std::atan2; using std::hypot;

    Type s[maxStack];
    label top = -1;

    for (label pc = 0; pc < n; ++pc)
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
            case opJumpIfZero: pc = (s[top--] == 0) ? c.arg - 1 : pc; break;
            case opJump: pc = c.arg - 1; break;
            case opNeg: s[top] = -a; break;
            case opNot: s[top] = Type(a == 0); break;
            case opSqr: s[top] = a*a; break;
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
            case opSign: s[top] = Type((a >= 0) ? 1 : -1); break;
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
            case opMin: s[top] = std::min(b, a); break;
            case opMax: s[top] = std::max(b, a); break;
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
    const dual result = run(code_.data(), code_.size(), x);
    derivative = result.d;
    return result.v;
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
