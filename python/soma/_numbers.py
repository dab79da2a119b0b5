"""Numbers between Python and soma's scalar ladder (used by the C++ module).

Results in long double, float128 and mpfr arrive as ``mpmath.mpf`` read at the scalar's own
precision from the decimal digits soma writes (io::numberText); arguments given as ``str``,
``int`` or ``mpmath.mpf`` are passed to soma's one number reader as decimal text.
"""
import mpmath
import numpy as np


def mpf(text, prec):
    """The decimal ``text`` as an mpmath.mpf with ``prec`` bits (soma writes inf, -inf, nan)."""
    with mpmath.workprec(prec):
        if text in ("inf", "-inf", "nan"):
            return mpmath.mpf({"inf": "inf", "-inf": "-inf", "nan": "nan"}[text])
        return mpmath.mpf(text)


def mpc(re_text, im_text, prec):
    """A complex result as an mpmath.mpc whose parts keep ``prec`` bits (mpmath.mpc(re, im) would
    round them to the current context's precision)."""
    with mpmath.workprec(prec):
        return mpmath.mpc(mpf(re_text, prec), mpf(im_text, prec))


def text(x, where):
    """Decimal text of a Python number other than float (floats are converted exactly in C++)."""
    if isinstance(x, str):
        return x
    if isinstance(x, (bool, np.bool_)):
        raise ValueError(f"{where}: a boolean is not a number")
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, np.floating):  # float32, longdouble: the shortest text that reads back the same
        return np.format_float_scientific(x, unique=True)
    if isinstance(x, mpmath.mpf):
        bits = max(x._mpf_[3], 53)
        return mpmath.libmp.to_str(x._mpf_, int(bits * 0.30103) + 3)
    raise ValueError(f"{where}: {type(x).__name__} {x!r} is not a number")


def flat(x, where):
    """The entries of a sequence or array, flattened, as a list."""
    try:
        return list(np.asarray(x, dtype=object).reshape(-1))
    except ValueError as e:  # ragged
        raise ValueError(f"{where}: not a regular array of numbers ({e})") from None
