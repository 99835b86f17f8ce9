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
              "/models/2/params/6/choices/8=hub-3" "/models/2/params/7/name=family"
              "/models/2/params/7/range={standard, given}" "/models/2/params/7/choices/1=given"
              "/models/2/params/8/name=samples" "/models/2/params/8/kind=integer"
              "/models/2/params/9/name=seed" "/models/2/params/9/default=1"
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
         STDOUT "mc-round  m=2 nbh=4 k=1 rho1=1/2 rho2=1/2 n=2 curve=line family=given samples=0 seed=1\n"
                "== lemma-6.4 \\(round-lemma\\): VIOLATED"
                "covered: m x m grids, m in \\{2 \\(counts 0..2\\)\\}; neighbourhood 4; curves \\{line\\} \\(q per region in units of sigma\\); k in \\{1\\}; rho2 in \\{1/2\\}; "
                "smallest counterexample: 5 robots, m = 2, claim L2\\(2\\)")
cli_test(mc_round_family_given_json EXIT 0
         ARGS check mc-round --prop lemma-6.5 --param m=2,nbh=8,n=3,curve=point,k=1,rho2=1/2,family=given --json
         JSON "/params/curve=point" "/params/family=given" "/params/samples=0" "/params/seed=1"
              "/properties/0/verdict=holds" "/properties/0/states=160" "/properties/0/edges=136"
              "type:/properties/0/figures/covered=string")

# samples > 0: the seeded random search; never "holds".
cli_test(mc_round_samples_fixpoint EXIT 3
         ARGS check mc-round --prop lemma-6.5 --param m=3,nbh=8,samples=20
         STDOUT "== lemma-6.5 \\(round-lemma\\): INCOMPLETE"
                "holds on 20 samples \\(a random search, not a proof\\)"
                "covered: random search, seed 1, 20 samples: m in 2..3, neighbourhood 8, curves \\{none, point, line, L, ring, all, line-1-3, checker-1-3, hub-3\\}"
                "states 20 ")
# The search finds conference Lemma 2(2)'s counterexample among 20 samples of hundreds of
# robots and shrinks it to the 5 robots of proofs/README.md.
cli_test(mc_round_samples_one_step EXIT 1
         ARGS check mc-round --prop lemma-6.4 --param m=3,nbh=4,samples=20
         STDOUT "== lemma-6.4 \\(round-lemma\\): VIOLATED"
                "violated: L2\\(2\\) \\(smallest counterexample: 5 robots, m = 2, claim L2\\(2\\)\\); 20 instances"
                "covered: random search, seed 1, 20 samples: m in 2..3, neighbourhood 4")
