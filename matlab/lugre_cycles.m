function r = lugre_cycles(u, gate, params, x0)
%LUGRE_CYCLES  Rainflow cycles (ASTM E1049-85, as `lugre cycles`) of a measured history.
%   r = lugre_cycles(u) counts the cycles of the history u; lugre_cycles(u, gate) ignores
%   reversals smaller than gate; with a parameter struct (see lugre_loop) each full cycle also
%   gets its energy: for LuGre along the rate-independent response y* from the bristle
%   deflection x0 (default 0); the struct names the model: sigma0 and fs, or preset =
%   'canudas1995' (energies of a measured history are not computed from the dimensionless
%   defaults). For a model of the zoo (params.model = 'maxwell-slip', ..., as lugre_loop takes
%   it; its parameters at the table's defaults unless given) along the model's path from rest
%   at u(1), as `lugre cycles --model NAME`: x0 is refused, and the history is held in memory
%   (at most 2^27 samples).
%   Returns column vectors: range, mean, count (1 full, 0.5 half), start, end, closure (sample
%   indices, 1-based as MATLAB counts: u(start) is where a cycle starts; closure 0 for half
%   cycles), closure_position (the 1-based position, with its fraction, where a full cycle
%   closes; 0 for half cycles), work, stored_energy_change, dissipation, closure_gap (0 for
%   half cycles or without a model). Numeric arguments of any real class or logical are taken
%   as double; a matrix is refused.
%   Example: r = lugre_cycles([0 4 1 3 -4 -1 -3 4 0], 0, struct('model', 'maxwell-slip'))
  if nargin < 2, gate = 0; end
  if nargin < 3, params = []; end
  if nargin < 4, x0 = []; end
  r = lugre_mex('cycles', u, gate, params, x0);
end
