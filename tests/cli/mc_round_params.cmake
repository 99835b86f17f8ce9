# mc-round's parameters that choose what a lemma property checks (included from
# CMakeLists.txt): parameters of kind choice (curve, family) in `list` and `list --json`,
# an unknown choice, family=given, and the seeded random search (samples, seed).

cli_test(list_choices EXIT 0 ARGS list
         STDOUT "\n    curve +default line +range choice +q per region: a named curve"
                "\n +one of: none, point, line, L, ring, all, line-1-3, checker-1-3, hub-3\n"
                "\n    family +default standard +range choice +lemma properties over: "
                "\n +one of: standard, given\n" "\n    samples +default 0 +range 0..100000 ")
cli_test(list_json_choices EXIT 0 ARGS list --json
         JSON "/models/2/name=mc-round" "/models/2/params/6/name=curve"
              "/models/2/params/6/kind=choice" "/models/2/params/6/default=line"
              "/models/2/params/6/lo=null" "/models/2/params/6/hi=null"
              "size:/models/2/params/6/choices=9" "/models/2/params/6/choices/0=none"
              "/models/2/params/6/choices/8=hub-3" "/models/2/params/7/name=curve_file"
              "/models/2/params/7/kind=text" "/models/2/params/8/name=config"
              "/models/2/params/9/name=family"
              "/models/2/params/9/range={standard, given}" "/models/2/params/9/choices/1=given"
              "/models/2/params/10/name=samples" "/models/2/params/10/kind=integer"
              "/models/2/params/11/name=seed" "/models/2/params/11/default=1"
              "/models/2/params/12/name=search_m" "/models/2/params/12/default=12"
              "/models/2/params/4/kind=rational" "not:/models/2/params/4/choices"
              "each:/models/2/params=name,kind,default,lo,hi,range,description")
cli_test(param_choice_unknown EXIT 2 ARGS check mc-round --param curve=zigzag
         NOT_STDOUT "."
         STDERR "^tioa-check: error: parameter curve: 'zigzag' is not one of none, point, line, L, ring, all, line-1-3, checker-1-3, hub-3\n$"
         STDERR_LINES 1)
cli_usage_error(param_family_unknown check mc-round --param family=mine)

# family=given: conference Lemma 2(2)'s counterexample (proofs/README.md) on its own family.
cli_test(mc_round_family_given EXIT 1
         ARGS check mc-round --prop lemma-6.4 --param m=2,nbh=4,n=2,curve=line,k=1,rho2=1/2,family=given
         STDOUT "mc-round  m=2 nbh=4 k=1 rho1=1/2 rho2=1/2 n=2 curve=line family=given samples=0 seed=1 search_m=12\n"
                "== lemma-6.4 \\(round-lemma\\): VIOLATED"
                "covered: m x m grids, m in \\{2 \\(counts 0..2\\)\\}; neighbourhood 4; curves \\{line\\} \\(q per region in units of sigma\\); k in \\{1\\}; rho2 in \\{1/2\\}; "
                "smallest counterexample: 5 robots, m = 2, claim L2\\(2\\)")
cli_test(mc_round_family_given_json EXIT 0
         ARGS check mc-round --prop lemma-6.5 --param m=2,nbh=8,n=3,curve=point,k=1,rho2=1/2,family=given --json
         JSON "/params/curve=point" "/params/family=given" "/params/samples=0" "/params/seed=1"
              "/properties/0/verdict=holds" "/properties/0/states=160" "/properties/0/edges=136"
              "type:/properties/0/figures/covered=string")

# samples > 0: the seeded random search, grids up to search_m (default 12), named curves
# and random grid paths; never "holds".
cli_test(mc_round_samples_fixpoint EXIT 3
         ARGS check mc-round --prop lemma-6.5 --param m=3,nbh=8,samples=20
         STDOUT "== lemma-6.5 \\(round-lemma\\): INCOMPLETE"
                "holds on 20 samples \\(a random search, not a proof\\)"
                "covered: random search, seed 1, 20 samples: m in 2..12, neighbourhood 8, a third of the samples a random grid path \\(proofs/random_curve.hpp\\), the rest curves \\{none, point, line, L, ring, all, line-1-3, checker-1-3, hub-3\\}"
                "states 20 ")
# The search finds conference Lemma 2(2)'s counterexample among 20 samples of hundreds of
# robots and shrinks it to 4 robots: on a curve with q = 1 and 2 (a random grid path),
# smaller than the 5 robots of the named curves (proofs/README.md).
cli_test(mc_round_samples_one_step EXIT 1
         ARGS check mc-round --prop lemma-6.4 --param m=3,nbh=4,samples=20
         STDOUT "== lemma-6.4 \\(round-lemma\\): VIOLATED"
                "violated: L2\\(2\\) \\(smallest counterexample: 4 robots, m = 2, claim L2\\(2\\)\\); 20 instances"
                "covered: random search, seed 1, 20 samples: m in 2..12, neighbourhood 4")

# A curve of one's own (issue 19): a q matrix or a polyline in a file (curve_file), and one
# configuration (config). Bad files are one line with the line to blame.
file(WRITE ${out}/zigzag_q.txt "# q per region\n. 1 . .\n1 2 1 .\n. . 3 1\n. . . 1\n")
file(WRITE ${out}/ring_polyline.txt
     "grid 3\nsigma 1/4\npolyline (1/2,1/2) (5/2,1/2) (5/2,5/2) (1/2,5/2)\nclosed\n")
file(WRITE ${out}/bad_row.txt "1 2\n3\n")
file(WRITE ${out}/one_config.json
     "{\"m\": 2, \"nbh\": 4, \"k\": 1, \"rho1\": \"1/2\", \"rho2\": \"1/2\",\n"
     " \"q\": [[0, 0], [1, 1]], \"robots\": [[0, 2], [2, 1]]}\n")
cli_test(mc_round_curve_file_matrix EXIT 0
         ARGS check mc-round -p curve_file=${out}/zigzag_q.txt,n=1,nbh=4 --prop lemma-6.1
         STDOUT "mc-round  nbh=4 k=1 rho1=1/2 rho2=9/10 n=1 curve_file=${out}/zigzag_q.txt samples=0"
                "== lemma-6.1 \\(round-lemma\\): HOLDS"
                "covered: m x m grids, m in \\{4 \\(counts 0..1\\)\\}; neighbourhood 4; curve file ${out}/zigzag_q.txt;")
cli_test(mc_round_curve_file_polyline EXIT 0
         ARGS check mc-round -p curve_file=${out}/ring_polyline.txt,n=1,nbh=4 --prop theorem-6.9
         STDOUT "== theorem-6.9 \\(round-lemma\\): HOLDS"
                "covered \\(positions\\): m x m grids of side 1, m in \\{3 \\(file ${out}/ring_polyline.txt\\)\\}; .* sigma = 1/4;")
cli_test(mc_round_curve_file_bad_row EXIT 2
         ARGS check mc-round -p curve_file=${out}/bad_row.txt
         STDERR "^tioa-check: error: model 'mc-round': parameter curve_file: .*bad_row.txt:2: this row has 1 entries, the first row \\(line 1\\) 2\n$"
         STDERR_LINES 1)
cli_test(mc_round_curve_file_and_curve EXIT 2
         ARGS check mc-round -p curve=ring -p curve_file=${out}/zigzag_q.txt
         STDERR "parameter curve_file replaces curve: give one of curve=ring and" STDERR_LINES 1)
cli_test(mc_round_curve_file_too_many EXIT 2
         ARGS check mc-round -p curve_file=${out}/zigzag_q.txt
         STDERR "start distributions \\(m = 4\\) is too many; lower n or m" STDERR_LINES 1)
# The configuration of conference Lemma 2(2)'s 5-robot counterexample (proofs/README.md):
# the claim fails along its run; Theorem 6.9 cannot place robots, so it is incomplete.
cli_test(mc_round_config_lemma EXIT 1
         ARGS check mc-round -p config=${out}/one_config.json --prop lemma-6.4
         STDOUT "mc-round  config=${out}/one_config.json\n"
                "== lemma-6.4 \\(round-lemma\\): VIOLATED"
                "coverage: all, 1 of 1: the configuration of ${out}/one_config.json and the run from it")
cli_test(mc_round_config_theorem EXIT 3
         ARGS check mc-round -p config=${out}/one_config.json --prop theorem-6.9
         STDOUT "part \\(2\\) with positions not checked: a configuration gives counts per region, not positions")
cli_test(mc_round_config_and_m EXIT 2
         ARGS check mc-round -p m=3 -p config=${out}/one_config.json
         STDERR "parameter config replaces m: give one of m=3 and" STDERR_LINES 1)
cli_test(mc_round_config_missing EXIT 2
         ARGS check mc-round -p config=${out}/no/such.json
         STDERR "^tioa-check: error: parameter config: round config: .*such.json: No such file" STDERR_LINES 1)

# round --curve-file: the curve's q in place of the configuration's (which may leave it out).
file(WRITE ${out}/no_q_config.json
     "{\"m\": 4, \"nbh\": 4, \"k\": 1, \"rho1\": \"1/2\", \"rho2\": \"9/10\",\n"
     " \"robots\": [[9, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]}\n")
cli_test(round_curve_file EXIT 0
         ARGS round --config ${out}/no_q_config.json --curve-file ${out}/zigzag_q.txt --to-fixpoint --json
         JSON "/T_stab=2" "/rounds/2/0/1=3")
cli_test(round_curve_file_other_grid EXIT 2
         ARGS round --config ${out}/one_config.json --curve-file ${out}/zigzag_q.txt
         STDERR "^tioa-check: error: round config '.*one_config.json': the curve file's grid is 4x4, the configuration's m = 2\n$")
cli_test(round_no_q EXIT 2 ARGS round --config ${out}/no_q_config.json
         STDERR "missing field 'q'" STDERR_LINES 1)
