//! Tests of the patch conversions.
