"""One decimal count per column (numbers.column_decimals): n significant digits of the
column's largest magnitude, within the caller's bounds — the rule the linkage report's M_b
column states (die_cutter 7 762.0 and 2.4, not 7762.013 and 2.384; a crank-rocker's 0.518
keeps three decimals). Values by hand: 4 significant digits of 7762.013 are 7762 (0
decimals), of 12.3 are 12.30 (2), of 0.00123 are 0.001230 (6)."""
from mechdesign.numbers import column_decimals


def test_significant_digits_of_the_largest_value():
    assert column_decimals(7762.013) == 0
    assert column_decimals(12.3) == 2
    assert column_decimals(0.00123) == 6
    assert column_decimals(9.999) == 3 and column_decimals(10.0) == 2
    assert column_decimals(12.3, n=3) == 1


def test_bounds_and_an_empty_column():
    assert column_decimals(7762.013, least=1, most=3) == 1      # die_cutter's M_b
    assert column_decimals(0.518, least=1, most=3) == 3         # crank_rocker's
    assert column_decimals(0.0, empty=3) == 3
    assert column_decimals(float("nan")) == 0
