//! Convergence records as a CSV table, for spreadsheets, plotting scripts and the book.

use std::path::Path;

use super::ConvergenceRecord;
use crate::output::{OutputError, write_text};

/// The first line of every convergence table.
pub const CONVERGENCE_CSV_HEADER: &str = "technique,spp,seconds,rmse,relmse";

/// Writes `records` as CSV, atomically: the header `technique,spp,seconds,rmse,relmse`, then
/// one row per record.
///
/// Numbers are written in Rust's shortest form that reads back to the same `f64` bit for bit,
/// so no precision is lost. A technique name containing a comma, quote or line break is quoted
/// as CSV demands.
pub fn write_convergence_csv(
    path: &Path,
    records: &[ConvergenceRecord],
) -> Result<(), OutputError> {
    write_text(path, &convergence_csv(records))
}

/// The CSV text of `records`.
fn convergence_csv(records: &[ConvergenceRecord]) -> String {
    let mut text = format!("{CONVERGENCE_CSV_HEADER}\n");
    for record in records {
        text.push_str(&format!(
            "{},{},{},{},{}\n",
            csv_field(&record.technique),
            record.spp,
            record.seconds,
            record.rmse,
            record.relmse
        ));
    }
    text
}

/// A text field, quoted (with inner quotes doubled) only when it has to be.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(technique: &str, spp: u64, seconds: f64, rmse: f64) -> ConvergenceRecord {
        ConvergenceRecord {
            technique: technique.into(),
            spp,
            seconds,
            rmse,
            relmse: rmse * rmse / 3.0,
        }
    }

    #[test]
    fn header_and_rows_parse_back_exactly() {
        let records = [
            record("independent", 1, 0.012_345_678_901_234_5, 0.1 + 0.2),
            record("stratified", 1024, 12.5, 1.0 / 3.0),
        ];
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("convergence.csv");
        write_convergence_csv(&path, &records).unwrap();

        let text = std::fs::read_to_string(&path).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("technique,spp,seconds,rmse,relmse"));
        let parsed: Vec<ConvergenceRecord> = lines
            .map(|line| {
                let fields: Vec<&str> = line.split(',').collect();
                assert_eq!(fields.len(), 5, "{line}");
                ConvergenceRecord {
                    technique: fields[0].to_string(),
                    spp: fields[1].parse().unwrap(),
                    seconds: fields[2].parse().unwrap(),
                    rmse: fields[3].parse().unwrap(),
                    relmse: fields[4].parse().unwrap(),
                }
            })
            .collect();
        assert_eq!(parsed, records, "every f64 reads back bit for bit");
    }

    #[test]
    fn awkward_names_are_quoted() {
        assert_eq!(csv_field("plain"), "plain");
        assert_eq!(csv_field("a, b"), "\"a, b\"");
        assert_eq!(csv_field("the \"best\""), "\"the \"\"best\"\"\"");
        let text = convergence_csv(&[record("cosine, 4x4", 16, 1.0, 0.5)]);
        assert_eq!(
            text.lines().nth(1),
            Some("\"cosine, 4x4\",16,1,0.5,0.08333333333333333")
        );
    }

    #[test]
    fn no_records_is_just_the_header() {
        assert_eq!(convergence_csv(&[]), "technique,spp,seconds,rmse,relmse\n");
    }
}
