% Van Roy benchmark 'poly_10', written for robocram from the benchmark's published
% description (Gabriel's "poly" benchmark): raise the polynomial 1+x+y+z to the 10th
% power symbolically. Not a copy of any distributed version. Entry point: top/0.
%
% A polynomial is a number or poly(Var, Terms): Terms is a list of term(Exp, Coef) in
% ascending Exp, each Coef a polynomial in variables after Var (order x, y, z).

top :- poly_test(P), poly_exp(10, P, R), poly_coef_sum(R, 1048576).

poly_test(P) :-
    poly_add(poly(x, [term(0, 1), term(1, 1)]), poly(y, [term(1, 1)]), Q),
    poly_add(poly(z, [term(1, 1)]), Q, P).

poly_var_before(x, y).
poly_var_before(x, z).
poly_var_before(y, z).

poly_add(P, Q, R) :- number(P), number(Q), !, R is P + Q.
poly_add(poly(V, Ts), Q, poly(V, Ts1)) :- number(Q), !, poly_add_const(Ts, Q, Ts1).
poly_add(P, poly(V, Ts), poly(V, Ts1)) :- number(P), !, poly_add_const(Ts, P, Ts1).
poly_add(poly(V, T1), poly(V, T2), poly(V, T)) :- !, poly_add_terms(T1, T2, T).
poly_add(poly(V1, T1), poly(V2, T2), poly(V1, T)) :-
    poly_var_before(V1, V2), !, poly_add_const(T1, poly(V2, T2), T).
poly_add(P, poly(V2, T2), poly(V2, T)) :- poly_add_const(T2, P, T).

% add C to the coefficient of exponent 0
poly_add_const([term(0, C0)|Ts], C, [term(0, C1)|Ts]) :- !, poly_add(C0, C, C1).
poly_add_const(Ts, C, [term(0, C)|Ts]).

poly_add_terms([], Ts, Ts) :- !.
poly_add_terms(Ts, [], Ts) :- !.
poly_add_terms([term(E, C1)|T1], [term(E, C2)|T2], [term(E, C)|T]) :- !,
    poly_add(C1, C2, C), poly_add_terms(T1, T2, T).
poly_add_terms([term(E1, C1)|T1], [term(E2, C2)|T2], [term(E1, C1)|T]) :-
    E1 < E2, !, poly_add_terms(T1, [term(E2, C2)|T2], T).
poly_add_terms(T1, [Term|T2], [Term|T]) :- poly_add_terms(T1, T2, T).

poly_mul(P, Q, R) :- number(P), number(Q), !, R is P * Q.
poly_mul(poly(V, Ts), Q, poly(V, Ts1)) :- number(Q), !, poly_scale(Ts, Q, Ts1).
poly_mul(P, poly(V, Ts), poly(V, Ts1)) :- number(P), !, poly_scale(Ts, P, Ts1).
poly_mul(poly(V, T1), poly(V, T2), poly(V, T)) :- !, poly_mul_terms(T1, T2, T).
poly_mul(poly(V1, T1), poly(V2, T2), poly(V1, T)) :-
    poly_var_before(V1, V2), !, poly_scale(T1, poly(V2, T2), T).
poly_mul(P, poly(V2, T2), poly(V2, T)) :- poly_scale(T2, P, T).

poly_scale([], _, []).
poly_scale([term(E, C)|Ts], K, [term(E, C1)|Ts1]) :- poly_mul(C, K, C1), poly_scale(Ts, K, Ts1).

poly_mul_terms([], _, []).
poly_mul_terms([term(E, C)|Ts], T2, T) :-
    poly_shift(T2, E, C, P), poly_mul_terms(Ts, T2, Rest), poly_add_terms(P, Rest, T).

poly_shift([], _, _, []).
poly_shift([term(E2, C2)|Ts], E, C, [term(E3, C3)|Ts3]) :-
    E3 is E + E2, poly_mul(C, C2, C3), poly_shift(Ts, E, C, Ts3).

poly_exp(0, _, 1) :- !.
poly_exp(N, P, R) :- 0 is N mod 2, !, M is N // 2, poly_exp(M, P, Q), poly_mul(Q, Q, R).
poly_exp(N, P, R) :- M is N - 1, poly_exp(M, P, Q), poly_mul(P, Q, R).

% the sum of all coefficients: (1+1+1+1)^10 = 1048576 checks the answer
poly_coef_sum(N, N) :- number(N), !.
poly_coef_sum(poly(_, Ts), S) :- poly_terms_sum(Ts, 0, S).
poly_terms_sum([], S, S).
poly_terms_sum([term(_, C)|Ts], S0, S) :- poly_coef_sum(C, S1), S2 is S0 + S1, poly_terms_sum(Ts, S2, S).
