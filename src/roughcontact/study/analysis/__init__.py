"""The study's analysis: merge, ensembles and statistics, ζ(H), crossover and exponents, grid error,
convergence, calibration and the models' scorecard (generated and measured surfaces alike)."""
