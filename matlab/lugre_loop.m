function r = lugre_loop(u, params, n)
%LUGRE_LOOP  The hysteresis loop of a model for a periodic input, with every minor loop.
%   r = lugre_loop(u, params) takes one period's turning points u (as
%   `lugre loop --turning-points`) and a parameter struct, and returns a struct. The struct
%   names the model in its field `model` (default 'lugre'):
%     LuGre  fields sigma0, sigma1, sigma2, fc, fs, vs, beta in SI units, or
%            preset = 'canudas1995'; missing fields take the CLI's defaults;
%     Dahl   model = 'dahl', fields rho, fc;
%     a model of the zoo (lugre_models lists them): model = 'maxwell-slip', ..., and its
%            parameters by name (lugre_parameters(model) lists them), each an array (one value
%            per element) or a number; missing ones take the table's defaults, e.g.
%            struct('model', 'maxwell-slip', 'stiffness', [1 2], 'slip_force', [1 0.5]).
%   lugre_loop(params, u) and lugre_loop(params, u, n), the struct first, are the same call.
%   Numbers of any real class (single, int32, ...) or logical are taken as double, in
%   arguments and fields; a matrix is refused:
%     r.u, r.rho, r.y      the turning points, the total variation there, the output there
%                          (y° for LuGre and Dahl, the force F for a model of the zoo) [N]
%     r.loops              the loop table (as `lugre loop --json`'s loops), column vectors:
%                          kind (0 major, 1 minor), start_/reversal_/end_ rho, u, y, work,
%                          stored_energy_change, dissipation, closure_gap, parent (the
%                          row of the enclosing loop, 1-based; 0: none), depth
%     r.work_per_period    the work per period [J], r.period [m]
%     r.curve              with n (lugre_loop(u, params, n), 2 <= n <= 1e8): the output at n
%                          points evenly spaced over the period, both ends included: columns
%                          r.curve.rho, r.curve.u, r.curve.y ([] without n)
%   Examples: r = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6))
%             r = lugre_loop([3 1 2 -3], struct('model', 'maxwell-slip', 'stiffness', [1 2], ...
%                                              'slip_force', [1 0.5]))
  if nargin >= 2 && isstruct(u) && ~isstruct(params)
    [u, params] = deal(params, u);
  end
  if nargin < 2
    params = struct();
  end
  if nargin < 3
    n = [];
  end
  r = lugre_mex('loop', u, params, n);
end
