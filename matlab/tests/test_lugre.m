function failures = test_lugre()
%TEST_LUGRE  The MEX functions against the CLI's JSON (to the last digit), MATLAB's habits
%   (any real numeric class or logical, 1-based indices in outputs and messages, matrices
%   refused) and bad input.
%   Run from the repository root after `bash scripts/build-mex.sh` and
%   `cargo build --release -p lugre-cli`:
%     octave --no-gui --quiet --eval "addpath('matlab', 'matlab/tests'); exit(test_lugre())"
%   Returns the number of failed checks (0: all passed). The CLI is $LUGRE_EXE or
%   target/release/lugre.
  failures = 0;
  exe = getenv('LUGRE_EXE');
  if isempty(exe)
    exe = 'target/release/lugre';
  end
  % Octave's jsondecode does not round every decimal correctly (it gave ...944 for
  % -1.9573070266459942): the numbers are read from the JSON text with str2double instead.
  cli = @(args) run_cli(exe, args);

  % The loop: y° at the turning points and the loop table, as `lugre loop --json`.
  r = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6));
  j = cli('loop --sigma0 6 --turning-points 0,1,0.5,1.5 --json');
  tp = between(j, '"turning_points":', '"loops":');
  failures += expect(isequal(r.y, numbers(tp, 'y')), 'loop: y at the turning points');
  failures += expect(isequal(r.rho, numbers(tp, 'rho')), 'loop: rho');
  failures += expect(isequal(r.loops.work, numbers(j, 'work')), 'loop: work of each loop');
  failures += expect(isequal(r.loops.closure_gap, numbers(j, 'closure_gap')), 'loop: closure gaps');
  failures += expect(isequal(r.work_per_period, numbers(j, 'work_per_period')), 'loop: work per period');
  kinds = regexp(j, '"kind":"(major|minor)"', 'tokens');
  failures += expect(isequal(r.loops.kind, strcmp([kinds{:}], 'minor')'), 'loop: kinds');
  % The minor loop's parent is the major loop's row (1-based); the major loop has none (0).
  major = find(r.loops.kind == 0);
  failures += expect(isequal(r.loops.parent(r.loops.kind == 1), major) && r.loops.parent(major) == 0, ...
                     'loop: parent rows, 1-based');

  % MATLAB's numeric classes and logical are taken as double, in arguments and struct fields.
  failures += expect(isequal(lugre_loop(single([0 1 0.5 1.5]), struct('sigma0', single(6))), r), ...
                     'single arguments and fields');
  failures += expect(isequal(lugre_loop(int32([0 2 1 3]), struct('sigma0', uint8(3))), ...
                             lugre_loop([0 2 1 3], struct('sigma0', 3))), 'integer arguments and fields');
  s1 = lugre_simulate(single([0 1 2]), uint16([0 1 0]), struct('preset', 'canudas1995', 'fs', true + 1));
  s2 = lugre_simulate([0 1 2], [0 1 0], struct('preset', 'canudas1995', 'fs', 2));
  failures += expect(isequal(s1, s2), 'single, uint16 and a logical expression');

  % A curve along the loop (lugre_loop(u, params, n)): n points over one period.
  r5 = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6), 5);
  failures += expect(isequal(r5.curve.rho', [0 1 2 3 4]) && r5.curve.y(1) == r.y(1) && r5.curve.y(5) == r.y(1), ...
                     'loop: the curve over one period');

  % Rainflow cycles with energies, as `lugre cycles --json`.
  h = [-2 1 -3 5 -1 3 -4 4 -2];
  c = lugre_cycles(h, 0, struct('sigma0', 6, 'fs', 2));
  j = between(cli('cycles --values -2,1,-3,5,-1,3,-4,4,-2 --energy --sigma0 6 --fs 2 --json'), ...
              '"cycles":', '"samples":');
  failures += expect(isequal(c.range, numbers(j, 'range')), 'cycles: ranges');
  failures += expect(isequal(c.count, numbers(j, 'count')), 'cycles: counts');
  % Indices are 1-based (the CLI's are 0-based): h(c.start) and h(c.end) are each cycle's ends.
  failures += expect(isequal(c.start, numbers(j, 'start') + 1), 'cycles: start indices, 1-based');
  failures += expect(isequal(c.end, numbers(j, 'end') + 1), 'cycles: end indices, 1-based');
  failures += expect(isequal(abs(h(c.start) - h(c.end))', c.range), 'cycles: h(start), h(end) span the range');
  full = c.count == 1;
  failures += expect(isequal(c.work(full), numbers(j, 'work')), 'cycles: work of the full cycle');
  failures += expect(isequal(lugre_cycles(int8(h), int16(0), struct('sigma0', int64(6), 'fs', 2)), c), ...
                     'cycles: int8 history, int16 gate, int64 field');
  failures += expect(isequal(lugre_cycles(logical([0 1 0 1 1 0])), lugre_cycles([0 1 0 1 1 0])), ...
                     'cycles: a logical history');
  failures += expect(isequal(c.closure(full), numbers(j, 'closure') + 1) && all(c.closure(~full) == 0), ...
                     'cycles: closure indices 1-based, 0 for half cycles');
  failures += expect(isequal(c.closure_position(full), numbers(j, 'closure_position') + 1), 'cycles: closure position, 1-based');

  % The closed-loop stick-slip experiment, as `lugre dynamics --json`.
  d = lugre_dynamics('stick-slip', [10 20 30]);
  j = cli('dynamics --scenario stick-slip --times 10,20,30 --json');
  failures += expect(isequal(d.x, array(j, 'x')), 'dynamics: x');
  failures += expect(isequal(d.friction, array(j, 'friction')), 'dynamics: friction');

  % The request, field by field as `lugre dynamics` takes flags: new gains on the PID
  % experiment keep its set point; the same doubles as the command line.
  d = lugre_dynamics(struct('scenario', 'pid', 'pid', int32([3 8 6]), 't_end', 20, 'samples', 11));
  j = cli('dynamics --scenario pid --pid 3,8,6 --t-end 20 --samples 11 --json');
  failures += expect(isequal(d.x, array(j, 'x')) && isequal(d.drive, array(j, 'drive')), 'dynamics request: x and drive as the CLI');
  failures += expect(d.t_end == 20 && d.stats.steps > 0 && isempty(d.breakaway), 'dynamics request: t_end, stats, no break-away');
  d = lugre_dynamics(struct('model', struct('preset', 'canudas1995'), 'force', [0 0; 1 1], 'times', 0:0.25:1));
  failures += expect(numel(d.t) == 5 && d.t_end == 1 && d.x(end) > 0, 'dynamics request: a force profile, the run to the last time');
  d = lugre_dynamics('pid');
  failures += expect(numel(d.x) == 1001 && d.t_end == 100, 'dynamics: a scenario alone');
  d = lugre_dynamics(struct('scenario', 'lag', 'times', 0:0.5:2));
  failures += expect(numel(d.x) == 5 && d.t_end == 2, 'dynamics request: times past the scenario''s end');
  d = lugre_dynamics(struct('scenario', 'breakaway', 'force_rate', single(4), 'samples', 3));
  failures += expect(d.t_end == 0.5 && d.breakaway.force > 1, 'dynamics request: the break-away at another rate');
  % The friction-displacement loops (GMS friction, the pre-sliding experiment): a struct array.
  d = lugre_dynamics(struct('scenario', 'presliding', 'model', struct('model', 'maxwell-slip'), 'samples', 5));
  l = d.loops;
  failures += expect(isstruct(l) && numel(l) >= 1 && iscolumn(l(1).turning_points) && numel(l(1).turning_points) >= 2 ...
                     && l(1).dissipation == l(1).work - l(1).bristle_energy_change && l(1).t_start < l(1).t_close, ...
                     'dynamics: the GMS loops as a struct array');
  d = lugre_dynamics(struct('scenario', 'pid', 't_end', 20, 'samples', 3));
  failures += expect(isstruct(d.loops) && isempty(d.loops) && isfield(d.loops, 'rate_independent_work'), ...
                     'dynamics: no loops, an empty struct array with the fields');

  % The friction element stepped through the knots is the exact simulation there.
  p = struct('preset', 'canudas1995');
  t = [0 5e-3 1e-2 1.5e-2 2e-2];
  x = [0 5e-6 1e-5 1e-5 -2e-6];
  s = lugre_simulate(t, x, p);
  [F, z] = lugre_friction_step(x(2:end), diff(t), p);
  failures += expect(isequal(z, s.z(2:end)), 'friction_step: z is the simulation''s');
  failures += expect(isequal(F(end), s.F(end)), 'friction_step: the last force');
  [F2, z2] = lugre_friction_step(x(4:end), diff(t(3:end)), p, z(2), x(3));
  failures += expect(isequal(z2, z(3:end)), 'friction_step: a run continued');

  % The steady-state sweep: the CLI's numbers to the last digit, amplitude-major.
  w = lugre_sweep([1e-6 1e-5], [0.1 1], struct('preset', 'canudas1995'));
  j = cli('sweep --preset canudas1995 --amplitudes 1e-6,1e-5 --frequencies 0.1,1 --json');
  failures += expect(isequal(w.amplitude, [1e-6; 1e-6; 1e-5; 1e-5]) && isequal(w.frequency, [0.1; 1; 0.1; 1]), ...
                     'sweep: the grid''s order');
  failures += expect(isequal(w.dissipation, numbers(j, 'dissipation')) && isequal(w.phase, numbers(j, 'phase')), ...
                     'sweep: the CLI''s energies and phases');
  failures += raises(@() lugre_sweep(0, 1), 'amplitudes: amplitude must be a finite number > 0, got 0');
  failures += raises(@() lugre_sweep(1e-6, [1 NaN]), 'frequencies: frequency must be a finite number > 0, got NaN');

  % Bad input: a MATLAB error with lugre's message, and Octave goes on.
  failures += raises(@() lugre_loop([0 NaN 1]), 'u(2) must be a finite number, got NaN');
  failures += raises(@() lugre_loop('abc'), 'u must be numeric or logical, got a char array');
  failures += raises(@() lugre_loop([0 1i]), 'u must be real, got a complex array');
  failures += raises(@() lugre_loop(ones(2)), 'u must be a vector (one row or one column), got a 2x2 array');
  failures += raises(@() lugre_loop(ones(1, 2, 2)), 'u must be a vector (one row or one column), got a 1x2x2 array');
  failures += raises(@() lugre_loop([0 1], struct('sigma0', ones(2))), 'params.sigma0 must be a vector (one row or one column), got a 2x2 array');
  failures += raises(@() lugre_cycles([0 1 2], ones(2)), 'gate must be a vector (one row or one column), got a 2x2 array');
  failures += raises(@() lugre_simulate(ones(3), ones(3)), 't must be a vector (one row or one column), got a 3x3 array');
  failures += raises(@() lugre_friction_step([0 1; 2 3], 1e-3), 'x must be a vector');
  failures += raises(@() lugre_loop([0 1 0.5 1.5], struct(), 1), 'n must be at least 2 (both ends of the period), got 1');
  failures += raises(@() lugre_loop([0 1], struct('sigma0', -1)), 'sigma0 must be > 0, got -1');
  failures += raises(@() lugre_loop([0 1], struct('sigma9', 1)), 'unknown parameter ''sigma9''');
  failures += raises(@() lugre_loop([0 1], struct('sigma0', [1 2])), 'sigma0 must be a scalar');
  failures += raises(@() lugre_simulate([0 1 2], [0 1]), 't and x have different lengths (3 and 2)');
  failures += raises(@() lugre_simulate([0 1 1], [0 1 2]), 'times must be strictly increasing: t(3) = 1 after t(2) = 1');
  failures += raises(@() lugre_friction_step([1e-6 2e-6], 0, p), 'cannot move in a zero step');
  failures += raises(@() lugre_dynamics('nope', [1 2]), 'unknown scenario ''nope''');
  failures += raises(@() lugre_dynamics(struct('scenario', 'pid', 'force_rate', 1, 'force', [0 1 2])), 'request.force must be an N-by-2 real matrix [t value], got a 1x3 double array');
  failures += raises(@() lugre_dynamics(struct('scenario', 'pid', 'force_rate', 1, 'force', [0 1; 1 2])), 'give force_rate or force, not both');
  failures += raises(@() lugre_dynamics(struct('scenario', 'presliding', 'setpoint', 1)), 'setpoint needs pid');
  failures += raises(@() lugre_dynamics(struct('force_rate', 1, 't_end', 1)), 'name the friction model');
  failures += raises(@() lugre_dynamics(struct('scenario', 'pid', 'samples', 1e12)), 'samples must be a whole number from 2 to 10000000');
  failures += raises(@() lugre_dynamics(struct('scenario', 'pid', 'pid', [1 2])), 'pid takes 3 numbers, got 2');
  failures += raises(@() lugre_dynamics(struct('scenario', 'pid', 'gamma', 1)), 'unknown field ''gamma''');
  failures += raises(@() lugre_cycles([0 Inf 1]), 'u(2) must be a finite number, got inf');
  % The parameter names, from the core's table through the C ABI.
  failures += expect(isequal(lugre_parameters('dahl'), {'rho', 'fc'}), 'lugre_parameters: Dahl');
  names = lugre_parameters();
  failures += expect(numel(names) == 7 && strcmp(names{1}, 'sigma0'), 'lugre_parameters: LuGre');
  failures += raises(@() lugre_parameters('no-such-model'), 'unknown model ''no-such-model'' (the models: ');
  failures += raises(@() lugre_parameters(3), 'model must be the name of a model');
  % Every model of the zoo, from the C ABI's table (none named here).
  failures += zoo_models(cli);
  failures += raises(@() lugre_cycles([0 1 0], 0, struct('fs', 1.5)), 'the model is only partly named: give sigma0 too, or preset ''canudas1995''');
  failures += raises(@() lugre_friction_step([1e-6 2e-6 3e-6], [1e-3 1e-3 0], p), 'step 3 (x(3)): the displacement cannot move in a zero step');

  % The fit, as `lugre fit --json` on the same samples (written with 17 digits: the same
  % doubles). The slow fit of the Example 4 loop with a small ripple (standard errors not 0).
  loop = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6), 401);
  u = loop.curve.u;
  f = loop.curve.y + 1e-3 * (mod((0:400)' * 7919, 13) - 6);
  fr = lugre_fit(u, f);
  j = cli(['fit --input ' record({'u', 'F'}, [u f]) ' --json']);
  failures += expect(isequal(fr.names, {'sigma0'; 'fs'}), 'fit: the slow fit''s parameters');
  failures += expect(isequal(fr.value, numbers(j, 'value')), 'fit: the slow fit''s estimates');
  failures += expect(isequal(fr.stderr, numbers(j, 'stderr')), 'fit: the slow fit''s standard errors');
  failures += expect(isequal(fr.rms, numbers(j, 'rms')) && fr.turning_points == 4 && fr.converged, ...
                     'fit: the slow fit''s residual, turning points, convergence');
  failures += expect(isequal(fr.residuals, f - fr.fitted) && fr.values.sigma0 == fr.value(1), ...
                     'fit: residuals and the fitted model''s values');
  failures += expect(abs(fr.value(1) - 6) < 3 * fr.stderr(1) && abs(fr.value(2) - 2) < 3 * fr.stderr(2), ...
                     'fit: the truth within three standard errors');
  failures += raises(@() lugre_fit(u, f(1:end - 1)), 'the data columns have different lengths: f has 400 values, u has 401');
  failures += raises(@() lugre_fit(u, f, struct('x0', 1)), 'options.x0 applies to the full fit (options.kind = ''full'')');
  failures += raises(@() lugre_fit(u, f, struct('fixx', 'sigma2')), 'unknown option ''options.fixx''');
  failures += raises(@() lugre_fit(u, f, struct('fix', 'sigma9')), 'options.fix: ');
  failures += raises(@() lugre_fit(u, f, struct('fix', {{'fs', 3}})), 'options.fix{2} must be a name');
  g = f; g(4) = NaN;
  failures += raises(@() lugre_fit(u, g), 'f(4) must be a finite number, got NaN');
  % A Dahl fit with Fc held at a given value (the parameters by name through the C ABI).
  fr = lugre_fit(u, f, struct('model', 'dahl', 'params', struct('fc', 2), 'fix', 'fc'));
  j = cli(['fit --input ' record({'u', 'F'}, [u f]) ' --model dahl --fc 2 --fix fc --json']);
  failures += expect(isequal(fr.names, {'rho'}) && isequal(fr.value, numbers(j, 'value')), ...
                     'fit: the Dahl fit''s estimate, Fc held by name');
  failures += raises(@() lugre_fit(u, f, struct('model', 'dahl', 'params', struct('sigma0', 1))), ...
                     'unknown parameter ''sigma0'' for the Dahl model (its parameters: rho, fc)');
  % The full fit of the paper's model swept at three speeds, sigma2 and beta held.
  t = 0; x = -6;
  for speed = [0.1 1 10]
    for target = [6 -6]
      k = (1:60)' / 60;
      t = [t; t(end) + abs(target - x(end)) / speed * k];
      x = [x; x(end) + (target - x(end)) * k];
    end
  end
  sim = lugre_simulate(t, x, struct());
  f = sim.F + 1e-3 * (mod((0:numel(t) - 1)' * 7919, 13) - 6);
  options = struct('kind', 'full', 't', t, 'params', struct(), 'fix', {{'sigma2', 'beta'}}, 'starts', 2);
  fr = lugre_fit(x, f, options);
  j = cli(['fit --input ' record({'t', 'u', 'F'}, [t x f]) ' --fit full --fix sigma2=0,beta=1 --starts 2 --json']);
  failures += expect(isequal(fr.names, {'sigma0'; 'sigma1'; 'fc'; 'fs'; 'vs'}), 'fit: the full fit''s parameters');
  failures += expect(isequal(fr.value, numbers(j, 'value')) && isequal(fr.stderr, numbers(j, 'stderr')), ...
                     'fit: the full fit''s estimates and standard errors');
  failures += expect(isempty(fr.turning_points) && strcmp(fr.kind, 'full') && fr.starts == 2, ...
                     'fit: the full fit''s report');
  failures += raises(@() lugre_fit(x, f, struct('kind', 'full')), 'a full fit (options.kind = ''full'') needs the sample times options.t');
  % A model of the zoo: the slow-loop fit of a Bouc-Wen loop, as `lugre fit --model bouc-wen`.
  bw = lugre_loop([2 -2], struct('model', 'bouc-wen', 'kx', 0.1, 'n', 2), 400);
  [~, k] = unique(bw.curve.rho(1:end - 1));
  u = bw.curve.u(k); f = bw.curve.y(k) + 1e-3 * (mod((0:numel(k) - 1)' * 7919, 13) - 6);
  fr = lugre_fit(u, f, struct('model', 'bouc-wen'));
  j = cli(['fit --input ' record({'u', 'F'}, [u f]) ' --model bouc-wen --json']);
  failures += expect(isequal(fr.names, {'kx'; 'kw'; 'rho'; 'sigma'; 'n'}) && strcmp(fr.model, 'bouc-wen'), ...
                     'fit: a zoo model''s parameters by name');
  failures += expect(isequal(fr.value, numbers(j, 'value')) && isequal(fr.stderr, numbers(j, 'stderr')), ...
                     'fit: a zoo model''s estimates and standard errors, as the CLI''s');
  failures += expect(fr.values.n == fr.value(5) && strcmp(fr.values.model, 'bouc-wen'), ...
                     'fit: the fitted zoo model''s values');
  failures += raises(@() lugre_fit(u, f, struct('model', 'elastoplastic', 'free', 'fc')), ...
                     'fc does not enter the slow loop of the elastoplastic model');
  failures += raises(@() lugre_fit(u, f, struct('elements', 3)), ...
                     'options.elements applies to an element model of the zoo');
  % A model of the zoo with a finite-rate form: the full fit of a record t,u,F of the
  % generator (crates/lugre/tests/reference/zoo_full_fit_reference.py), as `lugre fit --fit full`.
  rec = 'crates/lugre/tests/reference/zoo_fit/elastoplastic-full-noisy.csv';
  d = dlmread(rec, ',', 1, 0);
  full = struct('model', 'elastoplastic', 'kind', 'full', 't', d(:, 1), 'starts', 1);
  fr = lugre_fit(d(:, 2), d(:, 3), full);
  j = cli(['fit --input ' rec ' --model elastoplastic --fit full --starts 1 --json']);
  failures += expect(isequal(fr.value, numbers(j, 'value')) && isequal(fr.stderr, numbers(j, 'stderr')), ...
                     'fit: the zoo''s full fit''s estimates and standard errors, as the CLI''s');
  failures += expect(strcmp(fr.kind, 'full') && fr.starts == 1 && isempty(fr.turning_points), ...
                     'fit: the zoo''s full fit''s report');
  full.model = 'bouc-wen';
  failures += raises(@() lugre_fit(d(:, 2), d(:, 3), full), 'the bouc-wen model has no finite-rate form');
  failures += raises(@() lugre_fit(d(:, 2), d(:, 3), struct('model', 'elastoplastic', 'starts', 2)), ...
                     'options.starts applies to the full fit');
  if failures == 0
    printf('test_lugre: all checks passed\n');
  else
    printf('test_lugre: %d checks FAILED\n', failures);
  end
end

function failures = zoo_models(cli)
% Each model of the zoo on its defaults and on given arrays: the CLI's JSON to the last digit,
% the struct first or second, any numeric class; bad input refused with the core's message.
  failures = 0;
  models = lugre_models();
  failures += expect(iscellstr(models) && numel(models) >= 2, 'lugre_models: the zoo''s names');
  u = [3 1 2 -3 0.5 -1];
  for i = 1:numel(models)
    model = models{i};
    [names, table] = lugre_parameters(model);
    failures += expect(isequal(names, {table.name}), [model ': lugre_parameters, names and table']);
    given = struct('model', model);
    flags = '';
    for k = 1:numel(table)
      d = table(k).default;
      % Element arrays twice as long (each default element twice: valid whatever the model's
      % own constraints are), scalars at their defaults: every parameter given.
      if strcmp(table(k).shape, 'elements')
        d = [d, d];
      else
        failures += expect(isscalar(d), [model ': a scalar default']);
      end
      given.(table(k).name) = d;
      flags = [flags sprintf(' --%s=%s', strrep(table(k).name, '_', '-'), strjoin(arrayfun(@(x) sprintf('%.17g', x), d, 'UniformOutput', false), ','))];
    end
    for c = {{struct('model', model), ''}, {given, flags}}
      [params, f] = deal(c{1}{:});
      r = lugre_loop(u, params, 7);
      j = cli(['loop --model ' model f ' --turning-points=3,1,2,-3,0.5,-1 --samples 7 --json']);
      tp = between(j, '"turning_points":', '"loops":');
      what = [model f];
      failures += expect(isequal(r.y, numbers(tp, 'y')) && isequal(r.rho, numbers(tp, 'rho')), [what ': the turning points']);
      failures += expect(isequal(r.loops.work, numbers(j, 'work')), [what ': work of each loop']);
      failures += expect(isequal(r.loops.dissipation, numbers(j, 'dissipation')), [what ': dissipation of each loop']);
      failures += expect(isequal(r.loops.stored_energy_change, numbers(j, 'stored_energy_change')), [what ': stored energy']);
      failures += expect(isequal(r.loops.closure_gap, numbers(j, 'closure_gap')), [what ': closure gaps']);
      failures += expect(isequal(r.work_per_period, numbers(j, 'work_per_period')) && isequal(r.period, numbers(j, 'period')), [what ': work per period']);
      failures += expect(isequal(r.curve.y, numbers(j(strfind(j, '"points":'):end), 'y')), [what ': the curve']);
      failures += expect(numel(r.loops.kind) == 3 && isequal(r.loops.parent, [0; 1; 1]), [what ': three loops, parents 1-based']);
      % The struct first, and other numeric classes, are the same call.
      failures += expect(isequal(lugre_loop(params, u, 7), r), [what ': the struct first']);
    end
    failures += expect(isequal(lugre_loop(int8(u * 2), struct('model', model)), lugre_loop(u * 2, struct('model', model))), ...
                       [model ': an int8 input']);
    % The force from rest at each sample of a record (lugre_simulate with params.model), as
    % `lugre simulate --model NAME --input --json`; LuGre's initial state z0 is refused.
    ts = [0 0.5 1 2 2.2 3.7 4];
    xs = [0 1 2.5 -1 -1.5 0.25 2];
    s = lugre_simulate(ts, xs, given);
    j = cli(['simulate --model ' model flags ' --input ' record({'t', 'u'}, [ts' xs']) ' --json']);
    failures += expect(isequal(s.F, array(j, 'y')) && isequal(s.t, ts') && isequal(s.x, xs'), ...
                       [model ': simulate, the CLI''s force']);
    failures += expect(isequal(fieldnames(s), {'t'; 'x'; 'F'}), [model ': simulate, the fields t, x, F']);
    failures += raises(@() lugre_simulate(ts, xs, given, 0), ...
                       'z0 is an option of LuGre''s and Dahl''s simulation; the ');
    % Bad input: the core's message, 1-based.
    bad = struct('model', model);
    bad.(table(1).name) = [NaN table(1).default(2:end)];
    if strcmp(table(1).shape, 'elements')
      failures += raises(@() lugre_loop(u, bad), [table(1).name '(1) must be ']);
    else
      failures += raises(@() lugre_loop(u, bad), [table(1).name ' must be ']);
    end
    failures += raises(@() lugre_loop(u, struct('model', model, 'no_such', 1)), ...
                       sprintf('the %s model has no parameter ''no_such'' (its parameters: %s)', model, strjoin(names, ', ')));
    bad = struct('model', model);
    bad.(table(1).name) = ones(2);
    failures += raises(@() lugre_loop(u, bad), ['params.' table(1).name ' must be a vector (one row or one column), got a 2x2 array']);
    bad.(table(1).name) = 'a';
    failures += raises(@() lugre_loop(u, bad), ['params.' table(1).name ' must be numeric or logical, got a char array']);
  end
  failures += raises(@() lugre_loop(u, struct('model', 'no-such-model')), 'unknown model ''no-such-model''');
  failures += raises(@() lugre_loop(u, struct('model', 3)), 'params.model must be the name of a model');
  % 'lugre' and 'dahl' by name are LuGre's and Dahl's loops.
  failures += expect(isequal(lugre_loop(u, struct('model', 'lugre', 'sigma0', 6)), lugre_loop(u, struct('sigma0', 6))), ...
                     'params.model = ''lugre''');
  dahl = lugre_loop([-1 1 0 0.5], struct('model', 'dahl', 'rho', 2, 'fc', 1.5));
  j = cli('loop --model dahl --rho 2 --fc 1.5 --turning-points=-1,1,0,0.5 --json');
  failures += expect(isequal(dahl.loops.work, numbers(j, 'work')), 'params.model = ''dahl'': the CLI''s Dahl loop');
end

function path = record(names, columns)
% A CSV file with a header and every number to 17 digits (read back as the same doubles).
  path = [tempname() '.csv'];
  fid = fopen(path, 'w');
  fprintf(fid, '%s\n', strjoin(names, ','));
  fprintf(fid, [strjoin(repmat({'%.17g'}, 1, numel(names)), ',') '\n'], columns');
  fclose(fid);
end

function text = run_cli(exe, args)
  [status, text] = system([exe ' ' args]);
  if status ~= 0
    error('the CLI failed: %s %s: %s', exe, args, text);
  end
end

function v = numbers(text, key)
% Every number after "key": in the JSON text (null skipped), in order, as a column.
  tokens = regexp(text, ['"' key '":(-?[0-9][0-9.eE+-]*)'], 'tokens');
  v = str2double([tokens{:}])';
end

function v = array(text, key)
% The numbers of the array "key":[...].
  body = regexp(text, ['"' key '":\[([^\]]*)\]'], 'tokens', 'once');
  v = str2double(strsplit(body{1}, ','))';
end

function s = between(text, from, to)
  a = strfind(text, from);
  b = strfind(text, to);
  s = text(a(1):b(1));
end

function failed = expect(ok, what)
  failed = ~ok;
  if failed
    printf('FAILED: %s\n', what);
  end
end

function failed = raises(f, message)
  failed = true;
  try
    f();
    printf('FAILED: no error (wanted "%s")\n', message);
  catch err
    if ~isempty(strfind(err.message, message)) && strcmp(err.identifier, 'lugre:error')
      failed = false;
    else
      printf('FAILED: error "%s" (%s), wanted "%s"\n', err.message, err.identifier, message);
    end
  end
end
