//! Structure-aware mutation of JSON inputs and of command lines: keys dropped, duplicated
//! or retyped, wrong lengths, extreme and non-finite-looking numbers (1e308, 1e-320, -0,
//! "NaN"), empty arrays, deep nesting, degrees 0..200, bad knots and weights, unicode, and
//! byte-level damage (truncation, flipped bytes) of the serialized text.

use serde_json::{Map, Number, Value, json};

use super::rng::Rng;

/// Numbers that break naive code.
const EXTREME: &[f64] = &[
    0.0,
    -0.0,
    1.0,
    -1.0,
    1e308,
    -1e308,
    1.7976931348623157e308,
    1e-320,
    -1e-320,
    5e-324,
    1e-300,
    1e300,
    1e16,
    0.5,
    2.0,
    64.0,
    65.0,
    200.0,
    1e9,
    4294967296.0,
];

/// Strings that look like numbers or are hostile.
const STRINGS: &[&str] = &[
    "NaN", "nan", "inf", "-inf", "Infinity", "1e999", "", "0x10", "π", "\u{202e}", "null", "\u{0}",
    "1,5", "ÿ̴̪", "🦀",
];

/// Keys the readers know, for retyping and adding.
const KEYS: &[&str] = &[
    "type",
    "points",
    "weights",
    "degree",
    "knots",
    "knots_u",
    "knots_v",
    "L",
    "lo",
    "hi",
    "segments",
    "breaks",
    "breaks_u",
    "breaks_v",
    "patches",
    "direction",
    "keep",
    "interval",
    "bezier",
    "id",
    "algorithm",
    "params",
    "input",
    "expected",
    "tol",
    "n",
    "m",
    "P",
    "r",
    "p",
];

/// Type names, some unknown.
const TYPES: &[&str] = &[
    "bezier",
    "bspline",
    "tensor",
    "triangle",
    "bspline-surface",
    "beziers",
    "bezier-patches",
    "wsgb",
    "interval-triangle",
    "circle",
    "BEZIER",
    "",
];

/// A hostile number or value in place of a number.
fn extreme(rng: &mut Rng) -> Value {
    match rng.below(8) {
        0 => json!(*rng.pick(STRINGS)),
        1 => Value::Null,
        2 => json!(u64::MAX),
        3 => json!(i64::MIN),
        4 => json!(rng.below(201)),
        5 => json!(-(rng.below(5) as i64) - 1),
        _ => Number::from_f64(*rng.pick(EXTREME)).map_or(Value::Null, Value::Number),
    }
}

/// A random value of any type (small).
fn any(rng: &mut Rng, depth: usize) -> Value {
    match rng.below(if depth > 3 { 4 } else { 7 }) {
        0 => extreme(rng),
        1 => json!(rng.pick(STRINGS)),
        2 => json!(rng.one_in(2)),
        3 => Value::Null,
        4 => json!([]),
        5 => json!(
            (0..rng.below(4))
                .map(|_| any(rng, depth + 1))
                .collect::<Vec<_>>()
        ),
        _ => {
            let mut m = Map::new();
            m.insert((*rng.pick(KEYS)).to_string(), any(rng, depth + 1));
            Value::Object(m)
        }
    }
}

/// Counts the nodes of `v` (to pick one uniformly).
fn size(v: &Value) -> usize {
    1 + match v {
        Value::Array(a) => a.iter().map(size).sum(),
        Value::Object(o) => o.values().map(size).sum(),
        _ => 0,
    }
}

/// Applies `f` to the `k`-th node of `v` in pre-order; true once applied.
fn apply_at(v: &mut Value, k: &mut usize, f: &mut dyn FnMut(&mut Value)) -> bool {
    if *k == 0 {
        f(v);
        return true;
    }
    *k -= 1;
    match v {
        Value::Array(a) => a.iter_mut().any(|x| apply_at(x, k, f)),
        Value::Object(o) => o.values_mut().any(|x| apply_at(x, k, f)),
        _ => false,
    }
}

/// Applies one structural mutation to a random node of `v`.
fn mutate_node(rng: &mut Rng, v: &mut Value) {
    let mut k = rng.below(size(v));
    apply_at(v, &mut k, &mut |node| mutate_here(rng, node));
}

/// One structural mutation of `node`.
fn mutate_here(rng: &mut Rng, node: &mut Value) {
    match node {
        Value::Array(a) => match rng.below(9) {
            0 => a.clear(),
            1 if !a.is_empty() => {
                let i = rng.below(a.len());
                a.remove(i);
            }
            2 if !a.is_empty() => {
                let i = rng.below(a.len());
                let x = a[i].clone();
                a.insert(i, x);
            }
            3 => a.push(any(rng, 0)),
            4 if !a.is_empty() => {
                let i = rng.below(a.len());
                a[i] = extreme(rng);
            }
            5 if !a.is_empty() => a.reverse(),
            6 if !a.is_empty() => {
                // Grow: repeat the whole list (lengths now wrong by a factor).
                let copy = a.clone();
                a.extend(copy);
            }
            7 => *node = nest(rng, node.clone()),
            _ => *node = any(rng, 0),
        },
        Value::Object(o) => match rng.below(6) {
            0 if !o.is_empty() => {
                let key = o
                    .keys()
                    .nth(rng.below(o.len()))
                    .cloned()
                    .unwrap_or_default();
                o.remove(&key);
            }
            1 if !o.is_empty() => {
                let key = o
                    .keys()
                    .nth(rng.below(o.len()))
                    .cloned()
                    .unwrap_or_default();
                o.insert(key, any(rng, 0));
            }
            2 => {
                o.insert((*rng.pick(KEYS)).to_string(), any(rng, 0));
            }
            3 => {
                o.insert("type".into(), json!(*rng.pick(TYPES)));
            }
            4 if o.contains_key("weights") => {
                o.insert("weights".into(), weights_like(rng, o.get("weights")));
            }
            _ => {
                o.insert("degree".into(), degree_like(rng));
            }
        },
        Value::Number(_) => {
            *node = match rng.below(4) {
                0 => any(rng, 0),
                1 => json!(-node.as_f64().unwrap_or(0.0)),
                _ => extreme(rng),
            }
        }
        _ => *node = any(rng, 0),
    }
}

/// A degree-like value: 0..200, a pair, huge, negative or non-integer.
fn degree_like(rng: &mut Rng) -> Value {
    match rng.below(6) {
        0 => json!(rng.below(201)),
        1 => json!([rng.below(201), rng.below(6)]),
        2 => json!(u64::MAX),
        3 => json!(-1),
        4 => json!(2.5),
        _ => json!(rng.below(8)),
    }
}

/// Weights with a non-positive, tiny or huge entry, or the wrong length.
fn weights_like(rng: &mut Rng, w: Option<&Value>) -> Value {
    let mut w = w.cloned().unwrap_or_else(|| json!([1.0]));
    if let Value::Array(a) = &mut w {
        if a.is_empty() || rng.one_in(4) {
            a.push(json!(1.0));
        } else {
            let i = rng.below(a.len());
            a[i] = json!(*rng.pick(&[0.0, -0.0, -1.0, 1e-320, 1e308, 1e-300]));
        }
    }
    w
}

/// `v` wrapped in 1..200 arrays (deep nesting).
fn nest(rng: &mut Rng, v: Value) -> Value {
    let depth = if rng.one_in(4) {
        130 + rng.below(70)
    } else {
        1 + rng.below(4)
    };
    (0..depth).fold(v, |acc, _| json!([acc]))
}

/// One mutated input text from a valid `v`: 1..4 structural mutations, then sometimes
/// byte-level damage of the text.
pub(crate) fn mutate(rng: &mut Rng, v: &Value) -> Vec<u8> {
    let mut v = v.clone();
    // A third of the cases run valid input (the success paths and their bounds are judged
    // too); the others carry 1..4 structural mutations.
    if rng.one_in(3) {
        return v.to_string().into_bytes();
    }
    let most = if rng.one_in(2) { 1 } else { 4 };
    let rounds = 1 + rng.below(most);
    for _ in 0..rounds {
        mutate_node(rng, &mut v);
    }
    let mut text = v.to_string().into_bytes();
    match rng.below(16) {
        0 if !text.is_empty() => text.truncate(rng.below(text.len())),
        1 if !text.is_empty() => {
            let i = rng.below(text.len());
            text[i] = *rng.pick(b"{}[],:\"0-e.9 \\\x00\xff");
        }
        2 => {
            let i = rng.below(text.len() + 1);
            text.splice(i..i, "\u{1F980}é\u{FEFF}".bytes());
        }
        _ => {}
    }
    text
}

/// Hostile values for a command-line option.
pub(crate) fn option_value(rng: &mut Rng) -> String {
    (*rng.pick(&[
        "0",
        "1",
        "2",
        "3",
        "-1",
        "-0",
        "1e308",
        "1e-320",
        "NaN",
        "inf",
        "200",
        "65",
        "64",
        "18446744073709551616",
        "",
        "1,",
        ",",
        "0.5,0.5",
        "1,2,3",
        "x",
        "1e-300",
        "0,0",
        "3,200",
        "1,-1",
    ]))
    .to_string()
}
