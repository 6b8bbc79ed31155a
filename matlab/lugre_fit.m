function r = lugre_fit(u, f, options)
%LUGRE_FIT  The LuGre (or Dahl) parameters from measured friction, as `lugre fit`.
%   r = lugre_fit(u, f) is the slow fit: sigma0 and fs = g(0) from one or more periods of a
%   slow periodic test, the displacement u [m] and the friction force f [N] at each sample
%   (the record closes from its last sample back to its first: trim start-up transients;
%   sample the reversals themselves). It fits the closed-form hysteresis loop.
%   r = lugre_fit(u, f, struct('kind', 'full', 't', t)) is the full fit: sigma0, sigma1,
%   sigma2, fc, fs, vs (beta held unless freed) from rate-dependent samples at the times t
%   [s] (strictly increasing), on the exact simulation; a NaN in f marks a sample with no
%   measured force.
%
%   options, a struct whose fields are all optional:
%     kind     'slow' (default) or 'full' (needs t)
%     t        the sample times (full fit only)
%     model    'lugre' (default), 'dahl' (parameters rho and fc) or a model of the zoo
%     params   the values the parameters that are not fitted keep: a parameter struct as
%              lugre_loop's (LuGre), or struct('rho', ..., 'fc', ...) (Dahl); without it a
%              held parameter must be given one (free parameters start from the data)
%     fix      names held at their params value: 'sigma2', 'sigma2,beta' or {'sigma2', 'beta'}
%              (a parameter whose value is 0 must be held: fitted ones are positive)
%     free     names fitted besides the default ones, e.g. 'beta' (full fit)
%     x0       the initial bristle deflection [m] (full fit; default 0)
%     starts   the number of start points (full fit; default 3)
%     elements an element model of the zoo: the number of elements on the grid spanning the
%              record's amplitude (default 4)
%
%   A model of the zoo (options.model = 'maxwell-slip', 'prandtl-ishlinskii', 'bouc-wen' or
%   'elastoplastic', as `lugre fit --model NAME`) is fitted to its slow loop: every parameter
%   of the loop by name (an element's weight as 'stiffness[0]'), options.params the start
%   values (a struct of the model's parameters; an element model's thresholds its own), fix
%   and free as above; r.values is the fitted model (r.values.model its name). A model with a
%   finite-rate form ('maxwell-slip' as GMS, 'elastoplastic') is also fitted in full
%   (options.kind = 'full' with options.t, and options.starts; as `lugre fit --model NAME
%   --fit full`): every parameter of its table on its exact path from rest at the record's
%   rate; another model is refused with the core's message.
%
%   r, a struct:
%     r.names          the fitted parameters' names (a cell column, in the model's order)
%     r.value          their estimates (column), r.stderr their standard errors (linearised
%                      covariance), r.ci95 their 95 % intervals (one row [lo hi] each),
%                      r.at_bound true where an estimate sits on a bound
%     r.values         every parameter of the fitted model (a struct: lugre_loop(u, r.values)
%                      runs the fitted LuGre model)
%     r.rms            the residual RMS [N]; r.samples, r.dof (samples - fitted parameters),
%                      r.t_quantile (the intervals' factor), r.condition_number,
%                      r.iterations, r.evaluations, r.starts
%     r.converged      false when the fit ran out of evaluations at a usable point (reported,
%                      with a warning lugre:notConverged)
%     r.turning_points the turning points the slow fit found ([] for a full fit)
%     r.model, r.kind  'lugre' or 'dahl', 'slow' or 'full'
%     r.fitted         the model's force at every sample (column), r.residuals = f - fitted
%   A parameter the data cannot determine is an error naming it (identifier lugre:error).
%
%   Example (the paper's Example 4 loop, sigma0 = 6 and fs = 2, sampled and fitted back):
%     h = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6), 401);
%     r = lugre_fit(h.curve.u, h.curve.y);
%     r.names', r.value'      % {'sigma0', 'fs'}, [6 2]
  if nargin < 3
    options = struct();
  end
  r = lugre_mex('fit', u, f, options);
end
