% Zener's lambda grid through the Approx-ViscoElastic-CoR toolbox (Chatterjee, James & Brogliato,
% https://github.com/ChattAbhi/Approx-ViscoElastic-CoR, commit 9a8f7b6; NOT included here).
%
% The toolbox's contact law u' = w - gam u^bet, w' = -u^alp + gtil is Eq. (10) in its first-integral
% form with alp = bet = 3/2, gam = lambda and gtil = 0 (no external load).
%
% Regenerate (writes src/zener_sym/data/peers_toolbox.csv; run from the repository root):
%   git clone https://github.com/ChattAbhi/Approx-ViscoElastic-CoR /tmp/cor && (cd /tmp/cor && git checkout 9a8f7b6)
%   sed -i "s/'Event',/'Events',/g" /tmp/cor/*.m   # Octave's odeset does not take MATLAB's abbreviation
%   octave-cli --no-gui --quiet --eval "addpath('/tmp/cor'); source('tools/peers/toolbox_cor.m')"
%
% Columns: lam; numeric (numericCOR, default tolerances; its contact ends at u = 0, the plate's
% criterion); ord1 (first-order expansion 1 - gam C0); ord2sp (second order with Schwager &
% Poeschel's constant, getCOR 'ord2schw-pos'); ord2approx (getCOR 'ord2approx', the default).
lam = (1:250) * 0.02;
out = zeros(numel(lam), 5);
warning('off', 'all');
for i = 1:numel(lam)
  g = lam(i);
  out(i, 1) = g;
  out(i, 2) = numericCOR(1.5, 1.5, g, 0);
  out(i, 3) = getCOR(1, 1, g, 1, 1.5, 1.5, 0, 0, 'ord1approx');
  out(i, 4) = getCOR(1, 1, g, 1, 1.5, 1.5, 0, 0, 'ord2schw-pos');
  out(i, 5) = getCOR(1, 1, g, 1, 1.5, 1.5, 0, 0, 'ord2approx');
end
fid = fopen('src/zener_sym/data/peers_toolbox.csv', 'w');
fprintf(fid, '# Approx-ViscoElastic-CoR (commit 9a8f7b6) under %s, alp = bet = 3/2, gtil = 0, gam = lambda\n', version());
fprintf(fid, 'lam,numeric,ord1,ord2sp,ord2approx\n');
fprintf(fid, '%.17g,%.17g,%.17g,%.17g,%.17g\n', out');
fclose(fid);
