//! Snapshot tests of the chapter's small outputs: warped samples and the chi-square table.
//! Every number comes from fixed seeds; they are compared up to floating-point noise
//! (`workbench::assert_close_snapshot!`), so a correct warp written differently still passes.

use ch02_monte_carlo::lab::figures::chi2_rows;
use ch02_monte_carlo::samples::samples_csv;
use ch02_monte_carlo::warps::Warp;

#[test]
fn first_samples_of_every_warp() {
    let mut text = String::new();
    for name in Warp::NAMES {
        let warp = Warp::from_name(name, None).unwrap();
        text.push_str(&format!("# {name}\n{}", samples_csv(&warp, 4, 1)));
    }
    workbench::assert_close_snapshot!("first_samples_of_every_warp", text);
}

#[test]
fn chi_square_table_at_ten_thousand_samples() {
    // Statistics to one decimal and p-values to three: enough to catch a changed warp or
    // test, and the naive disc's failure is plain to see.
    let text: String = chi2_rows(10_000)
        .iter()
        .map(|(name, r)| {
            format!(
                "{name:<26} X2 {:>10.1}  dof {:>5}  p {:.3}\n",
                r.statistic, r.dof, r.p_value
            )
        })
        .collect();
    workbench::assert_close_snapshot!("chi_square_table_at_ten_thousand_samples", text);
}
