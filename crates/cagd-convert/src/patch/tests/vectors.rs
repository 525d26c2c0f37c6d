//! The public spec vectors of §15.4–15.7 through the library (the CLI's `cagd check` runs
//! them too; this is the library-level check).

use cagd_testkit::{assert_close, flat, inner_dim, num, vector};

use crate::patch::{
    PatchSurface, TensorSurface, TriSurface, corner_triangle, curve_split_d5, curve_split_d7,
    degenerate_rect_to_triangle, rect_to_two_triangles, trapezoid, triangle_to_degenerate_rect,
    triangle_to_rect_d1,
};

const FILE: &str = "vectors-convert.json";

/// `params.<key>` as a degree.
fn deg(v: &cagd_testkit::serde_json::Value, key: &str) -> Option<usize> {
    v["params"][key]
        .as_u64()
        .and_then(|x| usize::try_from(x).ok())
}

fn tri(v: &cagd_testkit::serde_json::Value) -> TriSurface {
    let p = &v["input"]["triangle_points"];
    let n = deg(v, "n").unwrap();
    TriSurface::new(flat(p), n, inner_dim(p), None).unwrap()
}

fn rect(v: &cagd_testkit::serde_json::Value) -> TensorSurface {
    let p = &v["input"]["rect_points"];
    let n = deg(v, "n").unwrap();
    let m = deg(v, "m").unwrap_or(n);
    TensorSurface::new(flat(p), m, n, inner_dim(p), None).unwrap()
}

fn tensor_points(s: &PatchSurface) -> Vec<f64> {
    match s {
        PatchSurface::Tensor(p) => p.net().points().to_vec(),
        PatchSurface::Tri(t) => t.net().points().to_vec(),
    }
}

#[test]
fn public_vectors() {
    let v = vector(FILE, "conv-15.4-n2");
    let got = triangle_to_degenerate_rect(&tri(&v), 2).unwrap();
    assert_close(
        "15.4",
        &tensor_points(&got.surface),
        &flat(&v["expected"]["rect_points"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.4-inv-n2");
    let got = degenerate_rect_to_triangle(&rect(&v), 1e-12).unwrap();
    assert_close(
        "15.4 inv",
        got.net().points(),
        &flat(&v["expected"]["triangle_points"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.5-n2-centroid");
    let q = |k: &str| num(&v["params"][k]);
    let got = triangle_to_rect_d1(&tri(&v), q("a"), q("b"), q("c"), q("d")).unwrap();
    assert_close(
        "15.5",
        &tensor_points(&got.surface),
        &flat(&v["expected"]["rect_points"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.6.1-a");
    let got = trapezoid(&rect(&v), num(&v["params"]["a"]), num(&v["params"]["b"])).unwrap();
    assert_close(
        "15.6.1",
        &tensor_points(&got.surface),
        &flat(&v["expected"]["rect_points"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.6.2-a");
    let got = corner_triangle(&rect(&v), num(&v["params"]["a"]), num(&v["params"]["b"])).unwrap();
    assert_close(
        "15.6.2",
        &tensor_points(&got.surface),
        &flat(&v["expected"]["rect_points"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.6.3-m2n1");
    let [lo, up] = rect_to_two_triangles(&rect(&v)).unwrap();
    assert_close(
        "15.6.3 lower",
        lo.net().points(),
        &flat(&v["expected"]["lower_triangle"]),
        num(&v["tol"]),
    );
    assert_close(
        "15.6.3 upper",
        up.net().points(),
        &flat(&v["expected"]["upper_triangle"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.7-D5-k2");
    let got = curve_split_d5(&rect(&v), &flat(&v["params"]["a"])).unwrap();
    assert_close(
        "15.7 D5",
        &tensor_points(&got.surface),
        &flat(&v["expected"]["rect_points"]),
        num(&v["tol"]),
    );

    let v = vector(FILE, "conv-15.7-D7-k2");
    let got = curve_split_d7(&rect(&v), &flat(&v["params"]["a"]), num(&v["params"]["b"])).unwrap();
    assert_close(
        "15.7 D7",
        &tensor_points(&got.surface),
        &flat(&v["expected"]["rect_points"]),
        num(&v["tol"]),
    );
}
