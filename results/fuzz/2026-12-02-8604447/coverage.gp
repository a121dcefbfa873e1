set terminal svg size 900,500 dynamic background rgb 'white'
set output '/work/main/results/fuzz/2026-12-02-8604447/coverage.svg'
set xlabel 'seconds into the target''s run'
set ylabel 'coverage (edges)'
set key bottom right
set logscale y
plot '/work/main/results/fuzz/2026-12-02-8604447/fuzz_clip_naive.coverage' using 1:2 with lines title 'fuzz_clip_naive','/work/main/results/fuzz/2026-12-02-8604447/fuzz_clip_sweep.coverage' using 1:2 with lines title 'fuzz_clip_sweep','/work/main/results/fuzz/2026-12-02-8604447/fuzz_clip_exact.coverage' using 1:2 with lines title 'fuzz_clip_exact','/work/main/results/fuzz/2026-12-02-8604447/fuzz_clip_exact_oracle.coverage' using 1:2 with lines title 'fuzz_clip_exact_oracle','/work/main/results/fuzz/2026-12-02-8604447/fuzz_diff_vatti.coverage' using 1:2 with lines title 'fuzz_diff_vatti','/work/main/results/fuzz/2026-12-02-8604447/fuzz_read.coverage' using 1:2 with lines title 'fuzz_read'
