//! Process measurements for the benches: CPU time and peak memory from /proc (Linux).

/// CPU time (user + system) of the process so far, seconds (from /proc; 0 if unknown): on a
/// shared machine the wall time depends on the other load, the CPU time less (it includes
/// the spinning of idle rayon workers).
pub fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/self/stat")
        .ok()
        .and_then(|s| {
            let rest = s.rsplit_once(')')?.1.split_whitespace().collect::<Vec<_>>();
            // Fields 14 and 15 (utime, stime) are at 11, 12 after the command name.
            let u: f64 = rest.get(11)?.parse().ok()?;
            let k: f64 = rest.get(12)?.parse().ok()?;
            Some((u + k) / 100.0)
        })
        .unwrap_or(0.0)
}

/// Peak resident memory of the process (VmHWM), bytes; 0 if unknown.
pub fn peak_rss() -> usize {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1).and_then(|v| v.parse::<usize>().ok()))
        })
        .map_or(0, |kb| kb * 1024)
}
