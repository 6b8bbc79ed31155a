function r = lugre_cycles(u, gate, params, x0)
%LUGRE_CYCLES  Rainflow cycles (ASTM E1049-85, as `lugre cycles`) of a measured history.
%   r = lugre_cycles(u) counts the cycles of the history u; lugre_cycles(u, gate) ignores
%   reversals smaller than gate; with a parameter struct (see lugre_loop) each full cycle also
%   gets its energy along the rate-independent response y* from the bristle deflection x0.
%   The struct names the model: sigma0 and fs, or preset = 'canudas1995' (energies of a
%   measured history are not computed from the dimensionless defaults).
%   Returns column vectors: range, mean, count (1 full, 0.5 half), start, end, closure (sample
%   indices, 1-based as MATLAB counts: u(start) is where a cycle starts; closure 0 for half
%   cycles), closure_position (the 1-based position, with its fraction, where a full cycle
%   closes; 0 for half cycles), work, stored_energy_change, dissipation, closure_gap (0 for
%   half cycles or without a model). Numeric arguments of any real class or logical are taken
%   as double; a matrix is refused.
  if nargin < 2, gate = 0; end
  if nargin < 3, params = []; end
  if nargin < 4, x0 = 0; end
  r = lugre_mex('cycles', u, gate, params, x0);
end
