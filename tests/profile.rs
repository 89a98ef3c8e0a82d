//! `blackhole profile`: the table, the JSON report (the documented shape plus
//! CPU phases) and the Chrome trace-event file, on lavapipe with validation.

mod common;

use common::{assert_clean, blackhole, path_in, run, scratch};

#[test]
fn profile_writes_report_and_trace() {
    let dir = scratch();
    let json = path_in(&dir, "p.json");
    let trace = path_in(&dir, "t.json");
    let mut c = blackhole();
    c.args([
        "profile", "--width", "64", "--height", "36", "--frames", "3", "--warmup", "2",
    ])
    .arg("--json")
    .arg(&json)
    .arg("--trace")
    .arg(&trace);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    assert!(
        stdout.contains("raymarch") && stdout.contains("CPU phase"),
        "{stdout}"
    );

    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(report["width"], 64);
    assert_eq!(report["frames"], 3);
    assert_eq!(report["warmup"], 2);
    assert!(report["device"].as_str().is_some_and(|d| !d.is_empty()));
    assert!(report["frame"]["median_ms"].as_f64().unwrap() > 0.0);
    let passes = report["passes"].as_array().unwrap();
    assert!(passes.iter().any(|p| p["name"] == "raymarch"));
    let cpu: Vec<&str> = report["cpu"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        cpu,
        ["build", "compile", "record", "submit", "wait", "readback"]
    );

    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&trace).unwrap()).unwrap();
    let events = t["traceEvents"].as_array().unwrap();
    let spans: Vec<&serde_json::Value> = events.iter().filter(|e| e["ph"] == "X").collect();
    // Three frames of six CPU phases and every GPU pass.
    let cpu_spans = spans.iter().filter(|e| e["tid"] == 1).count();
    let gpu_spans: Vec<_> = spans.iter().filter(|e| e["tid"] == 2).collect();
    assert_eq!(cpu_spans, 3 * 6);
    assert_eq!(gpu_spans.len(), 3 * passes.len());
    assert_eq!(
        gpu_spans.iter().filter(|e| e["name"] == "raymarch").count(),
        3
    );
    // GPU passes of a frame run one after another, and frames do not overlap.
    let mut end = f64::MIN;
    for e in gpu_spans {
        let (ts, dur) = (e["ts"].as_f64().unwrap(), e["dur"].as_f64().unwrap());
        assert!(dur >= 0.0 && ts >= end - 1e-3, "GPU span overlaps: {e}");
        end = ts + dur;
    }
    // Both tracks are named for Perfetto.
    assert!(
        events
            .iter()
            .any(|e| e["ph"] == "M" && e["args"]["name"] == "GPU passes")
    );
}
