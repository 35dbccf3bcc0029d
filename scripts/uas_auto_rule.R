# Scores rules that pick UAS's clustering method per run, against run cost, from an `amp bench` output
# of problems/experiments/uas-auto.yaml (common seeds: run i builds the same training roadmap under
# every method). Each run's features come from the uas-auto record (silhouette_<m>, clusters_<m>);
# a rule's cost in run i is the CD calls of the uas-<picked method> run i. Prints per problem and
# rule: the median and mean cost, their ratio to always-k-means, and the paired Wilcoxon signed-rank
# p against always-k-means; and the rank correlation of two methods' costs over the same training
# roadmaps (how much of a run's cost the training roadmap decides, i.e. what any per-run rule can gain).
# Optional analysis helper (R is not a build dependency: apt-get install r-base-core).
# Usage: Rscript scripts/uas_auto_rule.R OUT_DIR
args <- commandArgs(TRUE)
if (length(args) < 1) stop("usage: Rscript scripts/uas_auto_rule.R OUT_DIR")
runs <- read.csv(file.path(args[1], "runs.csv"))
methods <- c("kmeans", "ward", "pgmeans")
extra_value <- function(extra, key) {
  m <- regmatches(extra, regexpr(paste0("(^|;)", key, "=[^;]*"), extra))
  if (length(m) == 0) NA else as.numeric(sub(".*=", "", m))
}
cat(sprintf("%-9s %-22s %9s %9s %6s %6s %10s %7s\n", "problem", "rule", "median", "mean", "med/k", "mean/k", "signed-rank", "picks k/w/p"))
for (p in unique(runs$problem)) {
  cost <- sapply(methods, function(m) {
    r <- runs[runs$problem == p & runs$planner == paste0("uas-", m), ]
    r$cd_calls[order(r$run)]
  })
  a <- runs[runs$problem == p & runs$planner == "uas-auto", ]
  a <- a[order(a$run), ]
  sil <- sapply(methods, function(m) sapply(a$extra, extra_value, key = paste0("silhouette_", m)))
  clu <- sapply(methods, function(m) sapply(a$extra, extra_value, key = paste0("clusters_", m)))
  n <- nrow(cost)
  pick <- list(
    "always kmeans" = rep(1, n), "always ward" = rep(2, n), "always pgmeans" = rep(3, n),
    "silhouette (auto)" = apply(sil, 1, which.max),
    "fewest clusters" = apply(clu, 1, which.min), "most clusters" = apply(clu, 1, which.max),
    "oracle (cheapest)" = apply(cost, 1, which.min))
  base <- cost[, 1]
  for (rule in names(pick)) {
    x <- cost[cbind(seq_len(n), pick[[rule]])]
    w <- if (all(x == base)) NA else suppressWarnings(wilcox.test(x, base, paired = TRUE)$p.value)
    picks <- tabulate(pick[[rule]], 3)
    cat(sprintf("%-9s %-22s %8.0fk %8.0fk %6.2f %6.2f %10.3g %4d/%d/%d\n", p, rule, median(x) / 1e3, mean(x) / 1e3,
                median(x) / median(base), mean(x) / mean(base), w, picks[1], picks[2], picks[3]))
  }
  cat(sprintf("%-9s Spearman rho of costs over the same training roadmaps: kmeans-ward %.2f, kmeans-pgmeans %.2f\n", p,
              cor(cost[, 1], cost[, 2], method = "spearman"), cor(cost[, 1], cost[, 3], method = "spearman")))
}
