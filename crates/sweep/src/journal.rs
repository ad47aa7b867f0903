//! Sweeps that survive a crash: the rows of finished points are appended to a journal
//! (`<stem>.partial.csv` beside the table) one by one, each written whole to the operating
//! system before the next point's, so a sweep whose process is killed loses at most the
//! points that were running. The journal is flushed to the disk (fsync) after a record when
//! [`SYNC_INTERVAL`] has passed since its last flush, and by a flusher thread every
//! [`SYNC_INTERVAL`] while records wait (so short points followed by a long one are not left
//! unflushed while it runs), so a crash of the machine itself (a node that fails, a power
//! cut) loses at most the points that were running and those that finished within that
//! interval before it; points of a second or more are flushed one by one, as before, and a
//! sweep of many short points does not wait for the disk after each (on a spinning or
//! network disk a flush takes milliseconds, as long as a small point's solve). [`Sweep::run_journaled`]
//! with `resume` reads the journal of an earlier run of the same sweep, runs only the points
//! it lacks, and assembles the table in point order: no point is solved twice, none is lost,
//! and the table is the one an uninterrupted run gives. A journal's torn last record (a kill
//! during a write) is dropped and its point solved again. The journal is removed once the
//! table is written (all or nothing: [`write_atomically`]).

use std::fs::{File, OpenOptions};
use std::io::{Read as _, Seek as _, SeekFrom, Write as _};
use std::path::{Path, PathBuf};
use std::sync::{Condvar, Mutex};
use std::time::{Duration, Instant};

use crate::{Cell, Kind, Shard, Sweep, Table, TableError};

/// The longest time a finished point's record stays in the journal without being flushed
/// to the disk (module docs): a machine that crashes loses at most the points finished
/// within this time before it (and those running); a killed process loses none of them.
pub const SYNC_INTERVAL: Duration = Duration::from_secs(1);

/// The journal of the table `stem` in `dir`.
pub fn journal_path(dir: &Path, stem: &str) -> PathBuf {
    dir.join(format!("{stem}.partial.csv"))
}

/// What [`Sweep::run_journaled`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct Journaled {
    /// The table of the shard, in point order.
    pub table: Table,
    /// Points whose rows were read from the journal of an earlier run.
    pub resumed: usize,
    /// Points solved by this run.
    pub solved: usize,
}

/// One CSV record (with its line end) of `cells`.
fn record<'a>(cells: impl Iterator<Item = &'a str>) -> Result<Vec<u8>, TableError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(cells).map_err(|e| TableError(format!("cannot write a journal row: {e}")))?;
    w.into_inner().map_err(|e| TableError(format!("cannot write a journal row: {e}")))
}

/// A cell of `kind` from its CSV text.
fn cell(kind: Kind, t: &str) -> Option<Cell> {
    Some(match kind {
        Kind::Int => Cell::Int(t.parse().ok()?),
        Kind::Float if t.is_empty() => Cell::Float(None),
        Kind::Float => Cell::Float(Some(t.parse().ok()?)),
        Kind::Text if t.is_empty() => Cell::Text(None),
        Kind::Text => Cell::Text(Some(t.to_string())),
    })
}

/// The rows of a journal by point (None: not in it), and the length of its intact prefix.
type JournalRows = (Vec<Option<Vec<Cell>>>, u64);

impl Sweep {
    /// The rows of the journal at `path` that belong to this sweep, by point, and the
    /// length of its intact prefix (bytes). A torn or unreadable record ends the journal.
    ///
    /// # Errors
    /// A [`TableError`] when the journal cannot be read or belongs to another sweep.
    fn read_journal(&self, path: &Path) -> Result<JournalRows, TableError> {
        let name = path.display();
        let mut text = Vec::new();
        File::open(path)
            .and_then(|mut f| f.read_to_end(&mut text))
            .map_err(|e| TableError(format!("cannot read the partial table {name}: {e}")))?;
        let columns = self.columns();
        let mut rows: Vec<Option<Vec<Cell>>> = vec![None; self.len()];
        let mut r = csv::ReaderBuilder::new().has_headers(false).from_reader(text.as_slice());
        let mut rec = csv::StringRecord::new();
        let header_ok = matches!(r.read_record(&mut rec), Ok(true))
            && rec.iter().eq(columns.iter().map(|(c, _)| c.as_str()));
        if !header_ok {
            return Err(TableError(format!(
                "{name} is not the partial table of this sweep (its columns differ)"
            )));
        }
        let mut intact = r.position().byte();
        let (id, count) = (self.id(), self.len() as i64);
        while let Ok(true) = r.read_record(&mut rec) {
            // A record is whole only when its line end was written.
            let end = r.position().byte();
            if end as usize > text.len() || text[end as usize - 1] != b'\n' {
                break;
            }
            let cells: Option<Vec<Cell>> = (rec.len() == columns.len())
                .then(|| columns.iter().zip(rec.iter()).map(|((_, k), t)| cell(*k, t)).collect())
                .flatten();
            let Some(cells) = cells else { break };
            if cells[1] != Cell::Text(Some(id.to_string())) || cells[2] != Cell::Int(count) {
                return Err(TableError(format!(
                    "{name} belongs to another sweep (another scene text, --vary or point count)"
                )));
            }
            let Cell::Int(i) = cells[0] else { break };
            match usize::try_from(i).ok().and_then(|i| rows.get_mut(i)) {
                Some(slot) => {
                    if slot.is_none() {
                        *slot = Some(cells);
                    }
                }
                None => break,
            }
            intact = end;
        }
        Ok((rows, intact))
    }

    /// Run the points of `shard` as [`Sweep::run`] does, appending each finished row to the
    /// journal at `journal` and flushing it to the disk; with `resume`, first read the
    /// journal of an earlier run of this sweep and run only the points it lacks. `done` is
    /// called after each point solved now.
    ///
    /// # Errors
    /// A [`TableError`] when the journal cannot be written, or, with `resume`, cannot be
    /// read or belongs to another sweep.
    pub fn run_journaled(
        &self,
        shard: Shard,
        time_limit: f64,
        journal: &Path,
        resume: bool,
        done: impl Fn(usize) + Sync,
    ) -> Result<Journaled, TableError> {
        let name = journal.display();
        let io =
            |e: std::io::Error| TableError(format!("cannot write the partial table {name}: {e}"));
        let (mut have, file) = if resume && journal.exists() {
            let (rows, intact) = self.read_journal(journal)?;
            let mut f = OpenOptions::new().read(true).write(true).open(journal).map_err(io)?;
            // Drop a torn last record before appending.
            f.set_len(intact).map_err(io)?;
            f.seek(SeekFrom::End(0)).map_err(io)?;
            (rows, f)
        } else {
            let mut f = File::create(journal).map_err(io)?;
            f.write_all(&record(self.columns().iter().map(|(c, _)| c.as_str()))?).map_err(io)?;
            f.sync_data().map_err(io)?;
            (vec![None; self.len()], f)
        };
        let todo: Vec<usize> = shard.points(self.len()).filter(|&i| have[i].is_none()).collect();
        let resumed = shard.points(self.len()).count() - todo.len();
        let file = Mutex::new(Open { file, synced: Instant::now(), dirty: false });
        let failure: Mutex<Option<TableError>> = Mutex::new(None);
        let fail = |e: TableError| {
            if let Ok(mut slot) = failure.lock() {
                slot.get_or_insert(e);
            }
        };
        // Set when the points are done, to stop the flusher.
        let finished = (Mutex::new(false), Condvar::new());
        let rows = std::thread::scope(|scope| {
            // The flusher: records written since the last flush reach the disk within
            // SYNC_INTERVAL, even while a long point runs after short ones (module docs).
            scope.spawn(|| {
                let (lock, wake) = &finished;
                let Ok(mut end) = lock.lock() else { return };
                while !*end {
                    end = match wake.wait_timeout(end, SYNC_INTERVAL) {
                        Ok((end, _)) => end,
                        Err(_) => return,
                    };
                    if let Err(e) = file.lock().map_err(|_| lock_err()).and_then(|mut j| j.sync(io))
                    {
                        fail(e);
                    }
                }
            });
            // Rows land in the order the points finish (not point order): each record names
            // its point, and the records are appended whole, one at a time under the lock,
            // so a kill can tear only the last; the file is flushed after a record once
            // SYNC_INTERVAL has passed since its last flush, and by the flusher. After a
            // failed write nothing more is appended (a record after a torn one could be
            // misread).
            let rows = self.run_points(&todo, time_limit, |i, row| {
                let append = || -> Result<(), TableError> {
                    if failure.lock().map_or(true, |f| f.is_some()) {
                        return Ok(());
                    }
                    let text: Vec<String> = row.iter().map(Cell::to_text).collect();
                    let bytes = record(text.iter().map(String::as_str))?;
                    let mut j = file.lock().map_err(|_| lock_err())?;
                    j.file.write_all(&bytes).map_err(io)?;
                    j.dirty = true;
                    if j.synced.elapsed() >= SYNC_INTERVAL {
                        j.sync(io)?;
                    }
                    Ok(())
                };
                if let Err(e) = append() {
                    fail(e);
                }
                done(i);
            });
            if let Ok(mut end) = finished.0.lock() {
                *end = true;
            }
            finished.1.notify_all();
            rows
        });
        if let Some(e) = failure.into_inner().ok().flatten() {
            return Err(e);
        }
        for (i, row) in todo.iter().zip(rows) {
            have[*i] = Some(row);
        }
        let rows = shard.points(self.len()).filter_map(|i| have[i].take()).collect();
        Ok(Journaled {
            table: Table { columns: self.columns(), rows },
            resumed,
            solved: todo.len(),
        })
    }
}

/// The open journal: the file, when it was last flushed to the disk, and whether records
/// were written since.
struct Open {
    file: File,
    synced: Instant,
    dirty: bool,
}

impl Open {
    /// Flush the records written since the last flush to the disk (nothing when there are
    /// none).
    fn sync(&mut self, io: impl Fn(std::io::Error) -> TableError) -> Result<(), TableError> {
        if self.dirty {
            self.file.sync_data().map_err(io)?;
            self.dirty = false;
            self.synced = Instant::now();
        }
        Ok(())
    }
}

fn lock_err() -> TableError {
    TableError("journal lock".into())
}

/// Write `bytes` to `path` all or nothing: a temporary file beside it, flushed to the disk,
/// then renamed over it (a reader sees the old file or the new one, never a part).
///
/// # Errors
/// The I/O error, naming the file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), TableError> {
    let tmp = path
        .with_extension(format!("{}.tmp", path.extension().and_then(|e| e.to_str()).unwrap_or("")));
    let e = |e: std::io::Error| TableError(format!("cannot write {}: {e}", path.display()));
    let mut f = File::create(&tmp).map_err(e)?;
    f.write_all(bytes).map_err(e)?;
    f.sync_all().map_err(e)?;
    drop(f);
    std::fs::rename(&tmp, path).map_err(e)?;
    // The rename itself is durable once the directory is flushed (where it can be opened).
    if let Some(dir) = path.parent().and_then(|d| File::open(d).ok()) {
        let _ = dir.sync_all();
    }
    Ok(())
}
