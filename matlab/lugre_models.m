function names = lugre_models()
%LUGRE_MODELS  The names of the zoo's models, from the core's table (besides 'lugre' and 'dahl').
%   names = lugre_models() is a cell array, e.g. {'maxwell-slip', 'prandtl-ishlinskii', ...}:
%   the names lugre_loop's params.model and lugre_parameters take.
  names = lugre_mex('models');
end
