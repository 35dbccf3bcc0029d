# Pairwise run-cost comparisons against one baseline planner, from an `amp bench` output directory:
# per problem and planner, the ratio of median CD calls, the Wilcoxon rank-sum test (location), the
# coefficients of variation, the Brown-Forsythe test (spread: one-way ANOVA on |x - median|), and the
# same test on log cost (relative spread, the CV's counterpart: scale-free), and the ratio of CVs with a
# 95% percentile bootstrap interval (2000 resamples of each group, fixed RNG seed): an interval
# below 1 says the planner's CV is lower than the baseline's.
# Optional analysis helper (R is not a build dependency: apt-get install r-base-core).
# Usage: Rscript scripts/pairwise_tests.R OUT_DIR [BASELINE=hybrid-prm]
args <- commandArgs(TRUE)
if (length(args) < 1) stop("usage: Rscript scripts/pairwise_tests.R OUT_DIR [BASELINE]")
runs <- read.csv(file.path(args[1], "runs.csv"))
baseline <- if (length(args) > 1) args[2] else "hybrid-prm"
brown_forsythe <- function(x, y) {
  z <- c(abs(x - median(x)), abs(y - median(y)))
  g <- factor(rep(1:2, c(length(x), length(y))))
  anova(lm(z ~ g))[["Pr(>F)"]][1]
}
cv <- function(x) 100 * sd(x) / mean(x)
cv_ratio_ci <- function(x, b, resamples = 2000) {
  set.seed(1)
  r <- replicate(resamples, cv(sample(x, replace = TRUE)) / cv(sample(b, replace = TRUE)))
  quantile(r, c(0.025, 0.975), names = FALSE)
}
cat(sprintf("%-10s %-26s %6s %10s %7s %7s %10s %10s %6s %6s %15s\n", "problem", "planner", "ratio", "wilcoxon", "CV",
            "CV base", "BF", "BF log", "sd/sd", "CV/CV", "95% interval"))
for (p in unique(runs$problem)) {
  b <- runs$cd_calls[runs$problem == p & runs$planner == baseline]
  if (length(b) < 2) next
  for (planner in unique(runs$planner[runs$problem == p])) {
    if (planner == baseline) next
    x <- runs$cd_calls[runs$problem == p & runs$planner == planner]
    w <- suppressWarnings(wilcox.test(x, b)$p.value)
    ci <- cv_ratio_ci(x, b)
    cat(sprintf("%-10s %-26s %6.2f %10.3g %6.1f%% %6.1f%% %10.3g %10.3g %6.2f %6.2f %7.2f-%-7.2f\n", p, planner,
                median(x) / median(b), w, cv(x), cv(b), brown_forsythe(x, b), brown_forsythe(log(x), log(b)),
                sd(x) / sd(b), cv(x) / cv(b), ci[1], ci[2]))
  }
}
