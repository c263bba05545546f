# Measured inputs (docs/guide/measured.md): the scans of `topography` cut into tiles, and the
# surfaces drawn from each `spectrum` per seed, pressed per radius; one merged file per surface.


# Read, level and square one scan in units.length; count its tiles.
checkpoint measured_surface:
    input:
        scan=lambda wc: TOPOGRAPHY[wc.topo]["file"],
    output:
        nc="results/measured_surface/{topo}.nc",
    log:
        "logs/measured_surface/{topo}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        entry=lambda wc: TOPOGRAPHY[wc.topo],
        # only what the surface depends on: another load or fit setting keeps the tiles' runs
        cfg={"units": config["units"], "tile": config["tile"]},
    script:
        "../scripts/measured_surface.py"


# One tile of one scan under one radius (free half-space).
rule measured_indent:
    input:
        surface=rules.measured_surface.output.nc,
    output:
        run="results/measured_indent/{topo}/R{radius}_tile{tile}.nc",
    log:
        "logs/measured_indent/{topo}/R{radius}_tile{tile}.log",
    wildcard_constraints:
        tile=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    params:
        job=lambda wc: study_measured.job_of(
            STUDY, "topography", wc.topo, float(wc.radius), int(wc.tile)
        ),
        solver_version=SOLVER_VERSION,  # bumped on purpose when results change
    script:
        "../scripts/measured_indent.py"


# The tiles of one scan: NetCDF groups sphere (radius, tile, force) and flat (tile, force).
rule measured_merge:
    input:
        surface=rules.measured_surface.output.nc,
        runs=tiles_of,
    output:
        nc="results/measured_merge/{topo}.nc",
    log:
        "logs/measured_merge/{topo}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        source="topography",
    script:
        "../scripts/measured_merge.py"


# One seeded surface of one measured spectrum under one radius.
rule spectrum_indent:
    input:
        table=lambda wc: SPECTRUM[wc.spec]["file"],
    output:
        run="results/spectrum_indent/{spec}/R{radius}_seed{seed}.nc",
    log:
        "logs/spectrum_indent/{spec}/R{radius}_seed{seed}.log",
    wildcard_constraints:
        seed=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    params:
        job=lambda wc: study_measured.job_of(
            STUDY, "spectrum", wc.spec, float(wc.radius), int(wc.seed)
        ),
        solver_version=SOLVER_VERSION,  # bumped on purpose when results change
    script:
        "../scripts/measured_indent.py"


# The seeds of one spectrum: groups sphere (radius, seed, force) and flat (seed, force).
rule spectrum_merge:
    input:
        runs=expand(
            rules.spectrum_indent.output.run,
            radius=RADII,
            seed=STUDY.seeds,
            allow_missing=True,
        ),
    output:
        nc="results/spectrum_merge/{spec}.nc",
    log:
        "logs/spectrum_merge/{spec}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        source="spectrum",
    script:
        "../scripts/measured_merge.py"


# The spectrum of one scan over its tiles, its self-affine fit and the models' k(F).
rule measured_spectrum:
    input:
        surface=rules.measured_surface.output.nc,
    output:
        csv="results/measured_spectrum/{topo}.csv",
        html=report(
            "results/measured_spectrum/{topo}.html",
            caption="../report/measured_fit_table.rst",
            category="Measured: {topo}",
            labels={"table": "spectrum fit"},
        ),
        nc="results/measured_spectrum/{topo}.nc",
    log:
        "logs/measured_spectrum/{topo}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["models"],  # the registered models and their code
    script:
        "../scripts/measured_spectrum.py"


# The scorecard of one scan: every model of the registry against the mean over its tiles.
rule measured_scorecard:
    input:
        merged=rules.measured_merge.output.nc,
        spectrum=rules.measured_spectrum.output.nc,
    output:
        csv="results/measured_scorecard/{topo}.csv",
        html=report(
            "results/measured_scorecard/{topo}.html",
            caption="../report/measured_scorecard.rst",
            category="Measured: {topo}",
            labels={"table": "model scorecard"},
        ),
    log:
        "logs/measured_scorecard/{topo}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["models"],  # the registered models and their code
    script:
        "../scripts/measured_scorecard.py"


# The report section of one scan: height map, spectrum with the fit, k(F) with the models.
rule measured_figures:
    input:
        surface=rules.measured_surface.output.nc,
        merged=rules.measured_merge.output.nc,
        spectrum=rules.measured_spectrum.output.nc,
    output:
        heights=report(
            "results/measured_figures/{topo}/height_map.png",
            caption="../report/measured_heights.rst",
            category="Measured: {topo}",
            labels={"figure": "height map"},
        ),
        psd=report(
            "results/measured_figures/{topo}/spectrum.png",
            caption="../report/measured_spectrum.rst",
            category="Measured: {topo}",
            labels={"figure": "spectrum and fit"},
        ),
        kf=report(
            "results/measured_figures/{topo}/stiffness.png",
            caption="../report/measured_stiffness.rst",
            category="Measured: {topo}",
            labels={"figure": "k(F) and models"},
        ),
    log:
        "logs/measured_figures/{topo}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/measured_figures.py"


# The report section of one spectrum: k(F) of its seeded surfaces with the band over seeds.
rule spectrum_figures:
    input:
        merged=rules.spectrum_merge.output.nc,
    output:
        kf=report(
            "results/spectrum_figures/{spec}/stiffness.png",
            caption="../report/spectrum_stiffness.rst",
            category="Spectrum: {spec}",
            labels={"figure": "k(F)"},
        ),
    log:
        "logs/spectrum_figures/{spec}.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/spectrum_figures.py"
