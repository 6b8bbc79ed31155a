function names = lugre_parameters(model)
%LUGRE_PARAMETERS  The parameter names of a model, from the core's table.
%   names = lugre_parameters('lugre') is {'sigma0', 'sigma1', 'sigma2', 'fc', 'fs', 'vs',
%   'beta'} (a cell array, in the order of the fit's arrays and the C ABI's LugreParams);
%   lugre_parameters('dahl') is {'rho', 'fc'}. The names are those the parameter structs of
%   lugre_loop, lugre_cycles, lugre_simulate and lugre_fit take.
  if nargin < 1, model = 'lugre'; end
  names = lugre_mex('parameters', model);
end
