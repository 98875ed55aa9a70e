//! Shards: a sweep split over the tasks of a batch engine (a Slurm job array, a Kubernetes
//! Indexed Job), shard `i` of `n` running the cases whose index is `i` modulo `n`.

use core::fmt;
use core::str::FromStr;

/// Slurm's index of the task in its job array.
pub const SLURM_TASK_ID: &str = "SLURM_ARRAY_TASK_ID";
/// Slurm's number of tasks in the job array.
pub const SLURM_TASK_COUNT: &str = "SLURM_ARRAY_TASK_COUNT";
/// Slurm's lowest task index of the array (`--array=1-8` starts at 1).
pub const SLURM_TASK_MIN: &str = "SLURM_ARRAY_TASK_MIN";
/// Kubernetes' index of the pod in an Indexed Job (0 to `completions − 1`).
pub const K8S_COMPLETION_INDEX: &str = "JOB_COMPLETION_INDEX";

/// Most shards a sweep may be split into: 100,000, the most pods a Kubernetes Indexed Job
/// runs (`completions`) and a hundred times Slurm's default array size (`MaxArraySize`
/// 1001). `sweep-merge` opens every shard's files at once, and a shard count from a typo or
/// a corrupted `sweep.json` (`1/18446744073709551615`) must not be taken for a real split.
pub const MAX_SHARDS: usize = 100_000;

/// Shard `index` of `count`: the cases `index`, `index + count`, `index + 2·count`, …
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    index: usize,
    count: usize,
}

/// Why a shard cannot be used or found.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ShardError {
    /// Not `I/N` with integers `0 <= I < N`.
    #[error("'{0}' is not a shard: write I/N with 0 <= I < N, e.g. 0/4, or auto")]
    Syntax(String),
    /// More shards than [`MAX_SHARDS`].
    #[error("{0} shards: a sweep is split into at most {MAX_SHARDS} shards")]
    TooMany(usize),
    /// `--shard auto` outside a Slurm job array and a Kubernetes Indexed Job.
    #[error(
        "--shard auto: neither {SLURM_TASK_ID} (a Slurm job array) nor {K8S_COMPLETION_INDEX} \
         (a Kubernetes Indexed Job) is set; give the shard as --shard I/N"
    )]
    NoBatchEngine,
    /// An environment variable that is not the integer it should be.
    #[error("--shard auto: {name}={value} is not a non-negative integer")]
    BadVariable {
        /// The variable.
        name: &'static str,
        /// Its value.
        value: String,
    },
    /// A Slurm array whose task index lies outside `min .. min + count`.
    #[error(
        "--shard auto: {SLURM_TASK_ID}={id} is not within the array's {count} tasks from \
         {min}: run the sweep on a contiguous array (--array=0-{})",
        count.saturating_sub(1)
    )]
    NotContiguous {
        /// The task's index.
        id: usize,
        /// The array's lowest index.
        min: usize,
        /// The array's number of tasks.
        count: usize,
    },
    /// In a Kubernetes Indexed Job, the number of shards must be given.
    #[error(
        "--shard auto: {K8S_COMPLETION_INDEX}={0} says which shard, but not of how many: give \
         --shards N (the Job's completions)"
    )]
    NoCount(usize),
    /// `--shards N` contradicts the batch engine's count.
    #[error("--shards {given}, but {SLURM_TASK_COUNT}={found}")]
    CountMismatch {
        /// `--shards`.
        given: usize,
        /// The environment's.
        found: usize,
    },
}

impl Shard {
    /// The whole sweep: shard 0 of 1.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Shard `index` of `count`, if `index < count <= MAX_SHARDS`.
    pub fn new(index: usize, count: usize) -> Option<Shard> {
        (index < count && count <= MAX_SHARDS).then_some(Shard { index, count })
    }

    /// Shard `index` of `count`, refusing a count over [`MAX_SHARDS`] by name and anything
    /// else that is no shard with `syntax`.
    fn checked(
        index: usize,
        count: usize,
        syntax: impl FnOnce() -> ShardError,
    ) -> Result<Shard, ShardError> {
        if count > MAX_SHARDS {
            return Err(ShardError::TooMany(count));
        }
        Shard::new(index, count).ok_or_else(syntax)
    }

    /// Its index, from 0.
    pub fn index(self) -> usize {
        self.index
    }

    /// The number of shards.
    pub fn count(self) -> usize {
        self.count
    }

    /// The number of cases this shard runs of a sweep of `cases`.
    pub fn len(self, cases: usize) -> usize {
        cases.saturating_sub(self.index).div_ceil(self.count)
    }

    /// The index of the `k`-th case this shard runs.
    pub fn case_at(self, k: usize) -> usize {
        self.index + k * self.count
    }

    /// The indices of the cases this shard runs of a sweep of `cases`, in order.
    pub fn cases(self, cases: usize) -> impl Iterator<Item = usize> {
        (self.index..cases).step_by(self.count)
    }

    /// True when this shard runs case `case`.
    pub fn has(self, case: usize) -> bool {
        case % self.count == self.index
    }

    /// The shard of a batch task, from its environment (`var` reads a variable): a Slurm
    /// job array's task (`SLURM_ARRAY_TASK_ID` less `SLURM_ARRAY_TASK_MIN`, of
    /// `SLURM_ARRAY_TASK_COUNT`), or a Kubernetes Indexed Job's pod (`JOB_COMPLETION_INDEX`
    /// of `shards`, the Job's `completions`). `shards`, when given with Slurm, must agree.
    ///
    /// # Errors
    /// A [`ShardError`] saying which variable is missing or wrong.
    pub fn from_env(
        var: impl Fn(&str) -> Option<String>,
        shards: Option<usize>,
    ) -> Result<Shard, ShardError> {
        let number = |name: &'static str| -> Result<Option<usize>, ShardError> {
            match var(name) {
                None => Ok(None),
                Some(value) => value
                    .trim()
                    .parse()
                    .map(Some)
                    .map_err(|_| ShardError::BadVariable { name, value }),
            }
        };
        if let Some(id) = number(SLURM_TASK_ID)? {
            let count = number(SLURM_TASK_COUNT)?.ok_or(ShardError::BadVariable {
                name: SLURM_TASK_COUNT,
                value: String::new(),
            })?;
            let min = number(SLURM_TASK_MIN)?.unwrap_or(0);
            if let Some(given) = shards.filter(|&n| n != count) {
                return Err(ShardError::CountMismatch {
                    given,
                    found: count,
                });
            }
            if count > MAX_SHARDS {
                return Err(ShardError::TooMany(count));
            }
            return id
                .checked_sub(min)
                .and_then(|index| Shard::new(index, count))
                .ok_or(ShardError::NotContiguous { id, min, count });
        }
        if let Some(index) = number(K8S_COMPLETION_INDEX)? {
            let count = shards.ok_or(ShardError::NoCount(index))?;
            return Shard::checked(index, count, || {
                ShardError::Syntax(format!("{index}/{count}"))
            });
        }
        Err(ShardError::NoBatchEngine)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = ShardError;

    /// `I/N`, e.g. `2/8`, with `N` at most [`MAX_SHARDS`].
    fn from_str(s: &str) -> Result<Shard, ShardError> {
        let bad = || ShardError::Syntax(s.to_string());
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let (i, n) = (
            i.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        Shard::checked(i, n, bad)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let vars: Vec<(String, String)> = vars
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        move |name| vars.iter().find(|(k, _)| k == name).map(|(_, v)| v.clone())
    }

    #[test]
    fn shards_split_the_cases_exactly_once() {
        let shards: Vec<Shard> = (0..3).map(|i| Shard::new(i, 3).unwrap()).collect();
        let mut all: Vec<usize> = shards.iter().flat_map(|s| s.cases(10)).collect();
        all.sort_unstable();
        assert_eq!(all, (0..10).collect::<Vec<_>>());
        assert_eq!(
            shards.iter().map(|s| s.len(10)).collect::<Vec<_>>(),
            [4, 3, 3]
        );
        assert_eq!(shards[1].case_at(2), 7);
        assert!(shards[1].has(7) && !shards[1].has(8));
        assert_eq!(Shard::new(5, 8).unwrap().len(3), 0);
        assert_eq!("2/8".parse(), Ok(Shard::new(2, 8).unwrap()));
        assert_eq!(
            "1/18446744073709551615".parse::<Shard>(),
            Err(ShardError::TooMany(usize::MAX))
        );
        assert_eq!(
            "0/1000000000".parse::<Shard>().unwrap_err().to_string(),
            "1000000000 shards: a sweep is split into at most 100000 shards"
        );
        assert_eq!(
            format!("0/{MAX_SHARDS}").parse::<Shard>().map(Shard::count),
            Ok(MAX_SHARDS)
        );
        assert_eq!(Shard::new(0, MAX_SHARDS + 1), None);
        for bad in ["8/8", "1", "a/2", "-1/2", "1/0"] {
            assert_eq!(
                bad.parse::<Shard>(),
                Err(ShardError::Syntax(bad.into())),
                "{bad}"
            );
        }
    }

    #[test]
    fn batch_engines_name_the_shard() {
        let slurm = env(&[
            (SLURM_TASK_ID, "4"),
            (SLURM_TASK_COUNT, "4"),
            (SLURM_TASK_MIN, "1"),
        ]);
        assert_eq!(Shard::from_env(&slurm, None), Ok(Shard::new(3, 4).unwrap()));
        assert_eq!(
            Shard::from_env(&slurm, Some(4)),
            Ok(Shard::new(3, 4).unwrap())
        );
        assert_eq!(
            Shard::from_env(&slurm, Some(5)),
            Err(ShardError::CountMismatch { given: 5, found: 4 })
        );
        let gap = env(&[(SLURM_TASK_ID, "7"), (SLURM_TASK_COUNT, "3")]);
        assert_eq!(
            Shard::from_env(gap, None).unwrap_err().to_string(),
            "--shard auto: SLURM_ARRAY_TASK_ID=7 is not within the array's 3 tasks from 0: run \
             the sweep on a contiguous array (--array=0-2)"
        );
        let k8s = env(&[(K8S_COMPLETION_INDEX, "2")]);
        assert_eq!(
            Shard::from_env(&k8s, Some(3)),
            Ok(Shard::new(2, 3).unwrap())
        );
        assert_eq!(Shard::from_env(&k8s, None), Err(ShardError::NoCount(2)));
        assert_eq!(
            Shard::from_env(env(&[(K8S_COMPLETION_INDEX, "x")]), Some(3)),
            Err(ShardError::BadVariable {
                name: K8S_COMPLETION_INDEX,
                value: "x".into()
            })
        );
        assert_eq!(
            Shard::from_env(&k8s, Some(MAX_SHARDS + 1)),
            Err(ShardError::TooMany(MAX_SHARDS + 1))
        );
        let huge = env(&[(SLURM_TASK_ID, "0"), (SLURM_TASK_COUNT, "4000001")]);
        assert_eq!(
            Shard::from_env(huge, None),
            Err(ShardError::TooMany(4_000_001))
        );
        assert_eq!(
            Shard::from_env(env(&[]), Some(3)),
            Err(ShardError::NoBatchEngine)
        );
    }
}
