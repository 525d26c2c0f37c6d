//! Tests of the rational to polynomial surface conversion.
